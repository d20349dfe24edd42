// Text put into the files the program writes for people: HTML (the write-up's page, the class report) and CSV (the
// class summaries).
//
// Invariants: html_escaped(t) shows as t in an HTML element or a quoted attribute (& < > " escaped); csv_field(t) is
// one CSV field holding t (quoted, its quotes doubled, when it has a comma, a quote or a line break).
#pragma once

#include <string>

namespace meshedit {

std::string html_escaped(const std::string& text);
std::string csv_field(const std::string& text);

}  // namespace meshedit
