#include "tessera/live/live_page.hpp"

namespace tessera::live {
namespace {

// live_page_html.inc: the bytes of live_page.html, written by CMake (src/live/CMakeLists.txt).
constexpr unsigned char kPage[] = {
#include "live_page_html.inc"
};

}  // namespace

std::string_view live_page_html() { return {reinterpret_cast<const char*>(kPage), sizeof kPage}; }

}  // namespace tessera::live
