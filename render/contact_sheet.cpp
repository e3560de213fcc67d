// Contact sheet with OpenImageIO. render_text needs a named font: Debian's fonts-dejavu-core is
// pulled in by OpenImageIO's dependencies and found by name; without it labels are skipped.
#include "render/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/core.h>
#include <cmath>
#include <stdexcept>

#include "output/disk_space.h"
#include "render/povray_command.h"

namespace raintrace::render {

std::vector<int> pick_evenly(const std::vector<int>& frames, int count) {
  const int n = static_cast<int>(frames.size());
  if (n <= count) return frames;
  if (count <= 1) return count == 1 ? std::vector<int>{frames.front()} : std::vector<int>{};
  std::vector<int> picked;
  for (int i = 0; i < count; ++i) {
    // Index i·(n−1)/(count−1), rounded: 0 and n−1 are always included.
    const auto index =
        static_cast<std::size_t>(std::lround(static_cast<double>(i) * (n - 1) / (count - 1)));
    picked.push_back(frames[index]);
  }
  return picked;
}

ContactSheetResult make_contact_sheet(const std::filesystem::path& out_dir,
                                      const std::vector<int>& frames, int count, int digits) {
  ContactSheetResult result;
  const auto chosen = pick_evenly(frames, count);
  if (chosen.empty()) return result;
  std::vector<OIIO::ImageBuf> cells;
  for (int f : chosen) {
    OIIO::ImageBuf in{(out_dir / developed_image_name(f, digits)).string()};
    if (!in.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
      throw std::runtime_error(
          fmt::format("contact sheet: cannot read frame {}: {}", f, in.geterror()));
    }
    cells.push_back(std::move(in));
  }
  const int w = cells[0].spec().width;
  const int h = cells[0].spec().height;
  const int n = static_cast<int>(cells.size());
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  const int gap = 4;
  const int label_h = std::clamp(h / 6, 12, 28);
  OIIO::ImageSpec spec{columns * (w + gap) + gap, rows * (h + label_h + gap) + gap, 3,
                       OIIO::TypeDesc::FLOAT};
  OIIO::ImageBuf sheet{spec};
  const float grey[3] = {0.12f, 0.12f, 0.12f};
  OIIO::ImageBufAlgo::fill(sheet, grey);
  bool labels = true;
  for (int i = 0; i < n; ++i) {
    const int x = gap + (i % columns) * (w + gap);
    const int y = gap + (i / columns) * (h + label_h + gap);
    OIIO::ImageBuf rgb =
        OIIO::ImageBufAlgo::channels(cells[static_cast<std::size_t>(i)], 3, {0, 1, 2});
    OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, rgb);
    if (labels) {
      const float white[3] = {1.0f, 1.0f, 1.0f};
      labels = OIIO::ImageBufAlgo::render_text(
          sheet, x + 2, y + h + label_h - label_h / 4,
          fmt::format("frame {}", chosen[static_cast<std::size_t>(i)]), label_h * 3 / 4,
          "DejaVuSans", white);
      if (!labels) result.note = "no font found (fonts-dejavu-core): contact sheet has no labels";
    }
  }
  const auto temp = out_dir / ".tmp.contact_sheet.png";
  if (!sheet.write(temp.string(), OIIO::TypeDesc::UINT8)) {
    std::filesystem::remove(temp);
    const std::string what = "contact sheet: cannot write " + temp.string();
    output::throw_if_out_of_space(out_dir, static_cast<std::uint64_t>(spec.width) * spec.height * 4,
                                  what);
    throw std::runtime_error(what + ": " + sheet.geterror());
  }
  std::filesystem::rename(temp, out_dir / "contact_sheet.png");
  result.path = out_dir / "contact_sheet.png";
  return result;
}

}  // namespace raintrace::render
