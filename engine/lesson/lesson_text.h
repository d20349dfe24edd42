// The simple markdown lessons write in say(), as plain text for a terminal (`meshedit lesson --headless`)
// or any place without a markdown renderer.
//
// The markdown lessons use: `# heading` lines, **bold**, *italic*, `code`, [text](url) links, `- ` list items
// and blank lines between paragraphs. Plain text keeps the words and the line structure: heading marks and
// emphasis marks go, code keeps its text verbatim (so `current_mesh()` or `h.next` survive), a link becomes
// "text (url)", list items keep their "- ".
#pragma once

#include <string>
#include <string_view>

namespace meshedit {

std::string markdown_to_plain(std::string_view markdown);

}  // namespace meshedit
