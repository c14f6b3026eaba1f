#pragma once
// The live view's page (src/live/live_page.html): one static HTML file with plain JavaScript,
// compiled into the library and served from memory at the live server's "/". It connects back
// to the same port over the Foxglove WebSocket protocol, decodes the CDR messages itself and
// draws the map, robots, paths and markers, with play / pause / step through what it received.
#include <string_view>

namespace tessera::live {

[[nodiscard]] std::string_view live_page_html();

}  // namespace tessera::live
