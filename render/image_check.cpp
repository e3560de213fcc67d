// Full decode (not just the header): a truncated PNG has a valid header but fails its IDAT/IEND.
#include "render/image_check.h"

#include <OpenImageIO/imagebuf.h>
#include <fmt/core.h>

namespace raintrace::render {

bool image_is_complete(const std::filesystem::path& path, int width, int height, std::string* why) {
  auto fail = [&](std::string reason) {
    if (why != nullptr) *why = std::move(reason);
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("missing");
  OIIO::ImageBuf buf{path.string()};
  if (!buf.read(0, 0, /*force=*/true)) return fail("unreadable: " + buf.geterror());
  const auto& spec = buf.spec();
  if (spec.width != width || spec.height != height) {
    return fail(fmt::format("{}x{} instead of {}x{}", spec.width, spec.height, width, height));
  }
  return true;
}

}  // namespace raintrace::render
