// The program's version: what `meshedit --version` prints and what a bug report (document/bug_report.h) says saved it.
#pragma once

namespace meshedit {

inline constexpr char kAppVersion[] = "meshedit 0.1";

}  // namespace meshedit
