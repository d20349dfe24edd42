// Base64 (RFC 4648, with padding): how a picture goes inside a page or a Markdown file as a data: address (the
// grader's failure pictures, the write-up's index.html).
#pragma once

#include <string>
#include <string_view>

namespace meshedit {

// The base64 text of `bytes`: 4 characters for each 3 bytes, '=' padding the last group.
std::string base64(std::string_view bytes);

}  // namespace meshedit
