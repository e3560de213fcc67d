// Frame values → POV-Ray text: each item's line is made in a bounds-checked buffer (Line) with
// number_format.h's writers and appended to its chunk's string. Large sections are cut into
// chunks that threads fill independently and join in order, so the bytes never depend on the
// thread count.
#include "povgen/frame_text.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "povgen/content_hash.h"
#include "povgen/ground_scene.h"
#include "povgen/number_format.h"
#include "povgen/ordered_chunks.h"

namespace raintrace::povgen {
namespace {

/// Items per chunk: big enough to amortise a thread hand-off, small enough that a chunk's text
/// (a few MB) stays reusable and warm instead of page-faulting fresh memory every frame.
constexpr std::size_t kChunk = 16384;
/// Typical bytes of one item's text, to reserve a chunk's buffer once: a streak's corner line
/// ~110, its two index lines ~40 each, a sphere line ~45.
constexpr std::size_t kItemBytes = 128;

/// One item's line of text (a sphere, a streak's corners, a quad's index triples), made in a
/// fixed buffer and appended to its chunk's string in one go. Every write checks the room left
/// first (the number writers are given the buffer's end), so a line can never overrun it.
class Line {
 public:
  void put(char c) {
    require(1);
    m_text[m_size++] = c;
  }
  void put(std::string_view piece) {
    require(piece.size());
    std::copy(piece.begin(), piece.end(), m_text.begin() + static_cast<std::ptrdiff_t>(m_size));
    m_size += piece.size();
  }
  void number(double v) { m_size = end_of(write_number(cursor(), limit(), v)); }
  void fixed5(double v) { m_size = end_of(write_fixed5(cursor(), limit(), v)); }
  void index(std::uint64_t v) { m_size = end_of(write_index(cursor(), limit(), v)); }
  void vec(const glm::vec3& v) {
    put('<');
    number(v.x);
    put(',');
    number(v.y);
    put(',');
    number(v.z);
    put('>');
  }
  /// Appends the line to `text` and starts the next one.
  void append_to(std::string& text) {
    text.append(m_text.data(), m_size);
    m_size = 0;
  }

 private:
  /// The longest line: a streak's 4 corners of 3 numbers each, with their punctuation.
  static constexpr std::size_t kCapacity = 16 * kMaxNumberChars;

  void require(std::size_t chars) const {
    if (chars > kCapacity - m_size) {
      throw std::length_error("write_frame_text: an item's text is longer than a line");
    }
  }
  char* cursor() { return m_text.data() + m_size; }
  char* limit() { return m_text.data() + kCapacity; }
  std::size_t end_of(const char* end) const {
    return static_cast<std::size_t>(end - m_text.data());
  }

  std::array<char, kCapacity> m_text{};
  std::size_t m_size = 0;
};

/// Sends text to the sink in order. Small pieces are gathered; large sections are cut into
/// chunks that worker threads fill, each into its own reused buffer, and the buffers go to
/// the sink in chunk order (from whichever worker filled them, one call at a time). Chunk
/// boundaries depend only on the item count, never on the thread count, and each item's text only
/// on the item: identical bytes always.
class Emitter {
 public:
  Emitter(const TextSink& sink, int threads)
      : m_sink(sink),
        m_workers(static_cast<std::size_t>(std::clamp(threads, 1, 64))),
        m_buffers(m_workers) {}

  void text(std::string_view piece) { m_pending += piece; }
  void number(double v) { append_number(m_pending, v); }
  void index(std::size_t v) { append_index(m_pending, v); }
  void flush() {
    if (!m_pending.empty()) m_sink(m_pending);
    m_pending.clear();
  }

  /// write(begin, end, buffer) appends the text of items [begin, end) to buffer. Each worker
  /// thread fills its own buffer, and hands it to the sink in chunk order (ordered_chunks).
  template <typename Write>
  void chunks(std::size_t count, const Write& write) {
    flush();
    ordered_chunks((count + kChunk - 1) / kChunk, static_cast<int>(m_workers),
                   [&](std::size_t c, std::size_t w) {
                     std::string& buffer = m_buffers[w];
                     buffer.clear();  // keeps its capacity from chunk to chunk
                     buffer.reserve(kChunk * kItemBytes);
                     write(c * kChunk, std::min(count, (c + 1) * kChunk), buffer);
                   },
                   [&](std::size_t, std::size_t w) { m_sink(m_buffers[w]); });
  }

 private:
  const TextSink& m_sink;
  std::size_t m_workers;
  std::vector<std::string> m_buffers;
  std::string m_pending;
};

void write_spheres(const std::vector<SphereValue>& spheres, std::size_t begin, std::size_t end,
                   std::string& text) {
  Line line;
  for (std::size_t i = begin; i < end; ++i) {
    const SphereValue& s = spheres[i];
    if (s.axis_ratio == 1.0f) {
      line.put("sphere{");
      line.vec(s.centre);
      line.put(',');
      line.number(s.radius);
      line.put("}\n");
    } else {
      // Flattened about its own centre: scale first, then move into place.
      line.put("sphere{0,");
      line.number(s.radius);
      line.put(" scale<1,");
      line.number(s.axis_ratio);
      line.put(",1>translate");
      line.vec(s.centre);
      line.put("}\n");
    }
    line.append_to(text);
  }
}

void write_sphere_union(Emitter& out, const std::vector<SphereValue>& spheres,
                        const char* material) {
  if (spheres.empty()) return;
  out.text("union{\n");
  out.chunks(spheres.size(), [&](std::size_t b, std::size_t e, std::string& text) {
    write_spheres(spheres, b, e, text);
  });
  out.text("material{");
  out.text(material);
  // hollow everywhere: a ray through a non-hollow object inside a media container (mist,
  // a streetlight's cone) loses the media behind it, which paints every drop as a dark hole.
  out.text("}\nno_shadow hollow\n}\n");
}

/// One streak's vertex line. Corners are written to 10 µm in fixed point (write_fixed5), not
/// with 7 significant digits: a streak is at least a pixel wide, and a pixel is far wider than
/// 10 µm wherever a streak is drawn.
void write_corners(Line& line, const std::array<glm::vec3, 4>& corners) {
  for (const glm::vec3& c : corners) {
    line.put('<');
    line.fixed5(c.x);
    line.put(',');
    line.fixed5(c.y);
    line.put(',');
    line.fixed5(c.z);
    line.put(">,");
  }
  line.put('\n');
}

/// Index triples of the two triangles of each quad: <v, v+1, v+2>, <v, v+2, v+3>.
void write_triangle_pairs(Line& line, std::uint64_t v) {
  line.put('<');
  line.index(v);
  line.put(',');
  line.index(v + 1);
  line.put(',');
  line.index(v + 2);
  line.put(">,<");
  line.index(v);
  line.put(',');
  line.index(v + 2);
  line.put(',');
  line.index(v + 3);
  line.put(">,\n");
}

/// The atlas cells a frame's streaks use, in cell order, and each cell's place among them:
/// only those cells get uv_vectors (the atlas has ~1 500 cells, a frame uses a few dozen).
struct UsedCells {
  std::vector<int> cells;          ///< used cell numbers, ascending
  std::vector<std::int32_t> slot;  ///< per atlas cell: its index in `cells`, or −1
};

UsedCells used_cells(const std::vector<StreakValue>& streaks, const StreakAtlasLayout& atlas) {
  UsedCells used;
  used.slot.assign(static_cast<std::size_t>(std::max(atlas.cells(), 0)), -1);
  for (const StreakValue& s : streaks) {
    const auto cell = static_cast<std::size_t>(s.cell);
    if (s.cell < 0 || cell >= used.slot.size()) {
      throw std::invalid_argument("write_frame_text: a streak's atlas cell is not in the atlas");
    }
    used.slot[cell] = 0;
  }
  for (std::size_t cell = 0; cell < used.slot.size(); ++cell) {
    if (used.slot[cell] < 0) continue;
    used.slot[cell] = static_cast<std::int32_t>(used.cells.size());
    used.cells.push_back(static_cast<int>(cell));
  }
  return used;
}

/// The uv_indices line of each used cell: the same few dozen bytes for every streak in that
/// cell, so they are written once per frame and copied.
std::vector<std::string> uv_index_lines(std::size_t cells) {
  std::vector<std::string> lines(cells);
  Line line;
  for (std::size_t slot = 0; slot < lines.size(); ++slot) {
    write_triangle_pairs(line, 4 * slot);
    line.append_to(lines[slot]);
  }
  return lines;
}

void write_streak_mesh(Emitter& out, const std::vector<StreakValue>& streaks,
                       const StreakAtlasLayout& atlas) {
  if (streaks.empty()) return;
  const std::size_t n = streaks.size();
  const UsedCells used = used_cells(streaks, atlas);
  out.text("mesh2{\nvertex_vectors{");
  out.index(4 * n);
  out.text(",\n");
  out.chunks(n, [&](std::size_t b, std::size_t e, std::string& text) {
    Line line;
    for (std::size_t i = b; i < e; ++i) {
      write_corners(line, streaks[i].corners);
      line.append_to(text);
    }
  });
  // One uv quad per used atlas cell, inset by half a texel so filtering never reads a
  // neighbour. Corners 0, 1 (trailing end) take the cell's top, 2, 3 (leading end) its bottom.
  out.text("}\nuv_vectors{");
  out.index(4 * used.cells.size());
  out.text(",\n");
  const double width = atlas.width();
  const double height = atlas.height();
  for (const int cell : used.cells) {
    const int row = cell / atlas.columns();
    const int column = cell % atlas.columns();
    const double u0 = (column * atlas.cell_width + 0.5) / width;
    const double u1 = ((column + 1) * atlas.cell_width - 0.5) / width;
    const double v0 = (row * atlas.cell_height + 0.5) / height;
    const double v1 = ((row + 1) * atlas.cell_height - 0.5) / height;
    const double uv[4][2] = {{u0, v1}, {u1, v1}, {u1, v0}, {u0, v0}};
    for (const auto& corner : uv) {
      out.text("<");
      out.number(corner[0]);
      out.text(",");
      out.number(corner[1]);
      out.text(">,");
    }
    out.text("\n");
  }
  out.text("}\nface_indices{");
  out.index(2 * n);
  out.text(",\n");
  out.chunks(n, [&](std::size_t b, std::size_t e, std::string& text) {
    Line line;
    for (std::size_t i = b; i < e; ++i) {
      write_triangle_pairs(line, 4 * i);
      line.append_to(text);
    }
  });
  const std::vector<std::string> uv_lines = uv_index_lines(used.cells.size());
  out.text("}\nuv_indices{");
  out.index(2 * n);
  out.text(",\n");
  out.chunks(n, [&](std::size_t b, std::size_t e, std::string& text) {
    for (std::size_t i = b; i < e; ++i) {
      text +=
          uv_lines[static_cast<std::size_t>(used.slot[static_cast<std::size_t>(streaks[i].cell)])];
    }
  });
  // Left out of reflections: a streak is a quad turned to the camera, its length and coverage
  // what the camera sees of the drop, so a mirror, looking at it from below, would show a
  // wrong streak; and every reflected ray off the wet road, the puddles and the glass crossed
  // the whole mesh (4-10 % of a 1280x720 final frame of the default, BENCHMARKS.md).
  out.text("}\ntexture{RT_StreakTexture}\nno_shadow no_reflection hollow\n}\n");
}

// How far a bolt's glow reaches, in radii of its channel.
constexpr float kBoltGlowRadii = 8.0f;

/// "<x,y,z>"
void write_point(Emitter& out, const glm::vec3& p) {
  out.text("<");
  out.number(p.x);
  out.text(",");
  out.number(p.y);
  out.text(",");
  out.number(p.z);
  out.text(">");
}

void write_cylinder(Emitter& out, const CylinderValue& c, float radius) {
  out.text("cylinder{");
  write_point(out, c.start);
  out.text(",");
  write_point(out, c.end);
  out.text(",");
  out.number(radius);
}

void write_sphere(Emitter& out, const glm::vec3& centre, float radius) {
  out.text("sphere{");
  write_point(out, centre);
  out.text(",");
  out.number(radius);
  out.text("}\n");
}

// A segment's core is drawn at least half a pixel wide, its emission scaled to keep its light.
float core_light(const CylinderValue& c, float light) {
  return c.core_radius > 0.0f ? light * c.radius / c.core_radius : 0.0f;
}

// Each group of segments three times: the channel itself (RT_BoltCore, widened to at least half
// a pixel with its light scaled to match); the copy of it that mirrors see in its place
// (RT_BoltMirrored, scene.inc: wider and fainter, the same light); and around it the light that
// rain and cloud scatter out of it (RT_BoltGlow, scene.inc), a merge so that segments meeting at
// a joint do not glow twice.
// All three draws' emission is per unit of surface, set for a trunk of kBoltLightTrunkRadius_m;
// a bolt whose trunk is drawn thinner or thicker has each scaled by the inverse, so that it sends
// the same light per metre of channel (before, halving trunk_radius_m halved the bolt's light).
void write_bolts(Emitter& out, const std::vector<BoltValue>& bolts) {
  if (bolts.empty()) return;
  // Bolts are light, not rain: the rain mask leaves them out.
  out.text("#if(RT_Mask=0)\n");
  for (const BoltValue& bolt : bolts) {
    if (bolt.segments.empty()) continue;
    const float light = bolt.brightness * (kBoltLightTrunkRadius_m / bolt.trunk_radius);
    out.text("union{\n");
    for (const CylinderValue& c : bolt.segments) {
      write_cylinder(out, c, c.core_radius);
      out.text(" RT_BoltCore(");
      out.number(core_light(c, light));
      out.text(")}\n");
    }
    out.text("no_shadow hollow\n#if(RT_BoltBlur>0) no_reflection #end\n}\n");
    out.text("#if(RT_BoltBlur>0)\nunion{\n");
    for (const CylinderValue& c : bolt.segments) {
      out.text("RT_BoltMirrored(");
      write_point(out, c.start);
      out.text(",");
      write_point(out, c.end);
      out.text(",");
      out.number(c.core_radius);
      out.text(",");
      out.number(core_light(c, light));
      out.text(")\n");
    }
    out.text("no_shadow hollow no_image no_radiosity\n}\n#end\nmerge{\n");
    for (const CylinderValue& c : bolt.segments) {
      write_cylinder(out, c, c.radius * kBoltGlowRadii);
      out.text("}\n");
      // The glow's pattern is the angle a ray meets its surface at, so a cylinder's flat end cap,
      // where it juts out of its bent neighbour at a kink, glowed as a round spot beside the
      // channel: a sphere at each end, a hair wider than the cylinder so that the cap's rim lies
      // inside too, holds the caps inside the merge.
      write_sphere(out, c.start, c.radius * kBoltGlowRadii * 1.001f);
      write_sphere(out, c.end, c.radius * kBoltGlowRadii * 1.001f);
    }
    out.text("RT_BoltGlow(");
    out.number(light);
    out.text(")\nno_shadow hollow\n}\n");
  }
  out.text("#end\n");
}

}  // namespace

void write_frame_text(const FrameValues& values, const TextSink& sink,
                      const StreakAtlasLayout& atlas, int threads) {
  Emitter out(sink, threads);
  out.text("// raintrace frame ");
  out.index(static_cast<std::size_t>(std::max(values.index, 0)));
  out.text("\n#version 3.7;\n#declare RT_Flash=");
  out.number(values.flash);
  out.text(";\n#declare RT_FlashPosition=<");
  out.number(values.flash_position.x);
  out.text(",");
  out.number(values.flash_position.y);
  out.text(",");
  out.number(values.flash_position.z);
  out.text(">;\n#declare RT_Time=");
  out.number(values.time_s);
  out.text(";\n");
  // A bolt passes behind buildings: its frame traces the full environment, not the plate.
  const bool bolts = std::any_of(values.bolts.begin(), values.bolts.end(),
                                 [](const BoltValue& b) { return !b.segments.empty(); });
  if (bolts) out.text("#declare RT_Bolts=1;\n");
  if (!values.ripples.empty()) {
    // The map's pixels' hash: the frame's text, and so its input hash, changes with them.
    const std::vector<std::uint16_t> pixels = ripple_pixels(values.ripples);
    out.text("#declare RT_RippleMap=\"" + ripple_map_name(values.index) + "\"; // " +
             content_hash(std::string_view(reinterpret_cast<const char*>(pixels.data()),
                                           pixels.size() * sizeof(pixels[0]))) +
             "\n");
  }
  out.text("#include \"scene.inc\"\n");
  write_sphere_union(out, values.drops, "RT_DropMaterial");
  write_streak_mesh(out, values.streaks, atlas);
  write_bolts(out, values.bolts);
  out.flush();
}

std::string frame_text(const FrameValues& values, const StreakAtlasLayout& atlas, int threads) {
  std::string text;
  // Typical sizes: ~190 bytes per streak, ~45 per sphere; one reservation, no regrowth.
  text.reserve(1024 + 200 * values.streaks.size() + 64 * values.drops.size());
  write_frame_text(
      values, [&text](std::string_view piece) { text += piece; }, atlas, threads);
  return text;
}

std::string mask_text(const std::string& frame_path) {
  // frame_path is built by frame_file_name() from fixed words and digits; refuse anything else
  // rather than quote it into POV-Ray text.
  const bool safe = !frame_path.empty() &&
                    std::all_of(frame_path.begin(), frame_path.end(),
                                [](char c) {
                                  return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                                         c == '_' || c == '/' || c == '.';
                                }) &&
                    frame_path.find("..") == std::string::npos && frame_path.front() != '/';
  if (!safe) throw std::invalid_argument("mask_text: not a frame file name: " + frame_path);
  return "// raintrace rain mask: the frame's rain in white on black\n#version 3.7;\n"
         "#declare RT_Mask=1;\n#include \"" +
         frame_path + "\"\n";
}

int frame_digits(int frame_count) {
  int digits = 1;
  for (int n = frame_count; n >= 10; n /= 10) ++digits;
  return std::max(4, digits);
}

std::string frame_file_name(const std::string& prefix, int number, int digits,
                            const std::string& extension) {
  std::string n = std::to_string(number);
  if (static_cast<int>(n.size()) < digits)
    n.insert(0, static_cast<std::size_t>(digits) - n.size(), '0');
  return prefix + "_" + n + extension;
}

}  // namespace raintrace::povgen
