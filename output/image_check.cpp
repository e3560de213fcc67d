// Full decode (not just the header): a truncated PNG has a valid header but fails its IDAT/IEND.
#include "output/image_check.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>
#include <array>
#include <cerrno>
#include <cstddef>
#include <fstream>
#include <system_error>
#include <vector>

#include "povgen/content_hash.h"

namespace raintrace::output {
namespace {

// A PNG ends with its IEND chunk: length 0, "IEND", CRC AE 42 60 82. Checking these 12 bytes
// first skips decoding files POV-Ray is still writing (and libpng's stderr noise about them).
bool png_has_end(const std::filesystem::path& path) {
  std::ifstream in{path, std::ios::binary | std::ios::ate};
  if (!in || in.tellg() < 12) return false;
  in.seekg(-12, std::ios::end);
  std::array<char, 12> tail{};
  in.read(tail.data(), tail.size());
  static constexpr std::array<unsigned char, 12> kIend{0,   0,   0,    0,    'I',  'E',
                                                       'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  for (std::size_t i = 0; i < tail.size(); ++i) {
    if (static_cast<unsigned char>(tail[i]) != kIend[i]) return false;
  }
  return true;
}

}  // namespace

bool image_is_complete(const std::filesystem::path& path, int width, int height, std::string* why) {
  auto fail = [&](std::string reason) {
    if (why != nullptr) *why = std::move(reason);
    return false;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("missing");
  if (path.extension() == ".png" && !png_has_end(path)) return fail("incomplete PNG (no IEND)");
  // ImageInput, not ImageBuf: ImageBuf asks OpenImageIO's shared ImageCache, which keeps the
  // size of the first file it saw at a path, and frames are rewritten at the same names.
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) return fail("unreadable: " + OIIO::geterror());
  const OIIO::ImageSpec spec = input->spec();
  if (spec.width != width || spec.height != height) {
    return fail(fmt::format("{}x{} instead of {}x{}", spec.width, spec.height, width, height));
  }
  std::vector<std::byte> pixels(spec.image_bytes());
  if (!input->read_image(0, 0, 0, spec.nchannels, spec.format, pixels.data())) {
    return fail("unreadable: " + input->geterror());
  }
  return true;
}

std::optional<FileFacts> file_facts(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT || errno == ENOTDIR) return std::nullopt;
    throw std::system_error(errno, std::generic_category(), "cannot read " + path.string());
  }
  FileFacts facts;
  povgen::ContentHasher hasher;
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      // A folder where an image is expected (EISDIR) is just not the image.
      if (error == EISDIR) return std::nullopt;
      throw std::system_error(error, std::generic_category(), "cannot read " + path.string());
    }
    hasher.update({buffer.data(), static_cast<std::size_t>(n)});
    facts.size += static_cast<std::uint64_t>(n);
  }
  ::close(fd);
  facts.hash = hasher.hex();
  return facts;
}

}  // namespace raintrace::output
