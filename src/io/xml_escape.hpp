// Text put into an XML document (a .vtu array name, an SVG label) with its special characters as
// entities, so that any text keeps the document well-formed.
#pragma once

#include <string>
#include <string_view>

namespace hocav {

// `text` with &, <, >, " and ' replaced by &amp; &lt; &gt; &quot; &apos;.
std::string xml_escaped(std::string_view text);

}  // namespace hocav
