// Frame values → POV-Ray text, written with write_number() into reserved buffers. Large
// sections are cut into chunks that threads fill independently and join in order, so the
// bytes never depend on the thread count.
#include "povgen/frame_text.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "povgen/number_format.h"

namespace raintrace::povgen {
namespace {

/// Characters one item can take at most, for reserving: a streak's 4 vertices are 12 numbers
/// plus punctuation; spheres 5 numbers; index triples 3 integers.
constexpr std::size_t kNumberSpace = max_number_chars + 1;

/// A small appender over a pre-sized buffer: no reallocation or bounds checks in the hot loops.
/// reserve_more() must cover everything put until the next reserve_more().
class Writer {
 public:
  explicit Writer(std::string& text) : m_text(text), m_used(text.size()) {}
  void reserve_more(std::size_t bytes) { m_text.resize(m_used + bytes); }
  void put(char c) { m_text[m_used++] = c; }
  void put(const char* s) {
    const std::size_t n = std::strlen(s);
    std::memcpy(&m_text[m_used], s, n);
    m_used += n;
  }
  void number(double v) {
    char* begin = &m_text[m_used];
    m_used += static_cast<std::size_t>(write_number(begin, v) - begin);
  }
  void index(std::uint64_t v) {
    char* begin = &m_text[m_used];
    m_used += static_cast<std::size_t>(write_index(begin, v) - begin);
  }
  void vec(const glm::vec3& v) {
    put('<');
    number(v.x);
    put(',');
    number(v.y);
    put(',');
    number(v.z);
    put('>');
  }
  void finish() { m_text.resize(m_used); }

 private:
  std::string& m_text;
  std::size_t m_used = 0;
};

/// Runs write(begin, end, text) over [0, count) in chunks, joining the chunks in order.
/// Chunk boundaries depend only on count, never on threads, so the output cannot either.
std::string write_chunks(std::size_t count, int threads,
                         const std::function<void(std::size_t, std::size_t, std::string&)>& write) {
  constexpr std::size_t kChunk = 16384;
  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<std::string> parts(chunks);
  auto run = [&](std::size_t first_chunk, std::size_t stride) {
    for (std::size_t c = first_chunk; c < chunks; c += stride) {
      write(c * kChunk, std::min(count, (c + 1) * kChunk), parts[c]);
    }
  };
  const auto workers = static_cast<std::size_t>(std::clamp(threads, 1, 64));
  if (workers == 1 || chunks <= 1) {
    run(0, 1);
  } else {
    std::vector<std::thread> pool;
    std::vector<std::exception_ptr> errors(workers);
    for (std::size_t w = 0; w < workers; ++w) {
      pool.emplace_back([&, w] {
        try {
          run(w, workers);
        } catch (...) {
          errors[w] = std::current_exception();
        }
      });
    }
    for (auto& t : pool) t.join();
    for (auto& e : errors) {
      if (e) std::rethrow_exception(e);
    }
  }
  std::size_t total = 0;
  for (const auto& p : parts) total += p.size();
  std::string joined;
  joined.reserve(total);
  for (const auto& p : parts) joined += p;
  return joined;
}

void write_spheres(const std::vector<SphereValue>& spheres, std::size_t begin, std::size_t end,
                   std::string& text) {
  Writer w(text);
  w.reserve_more((end - begin) * (8 * kNumberSpace + 40));
  for (std::size_t i = begin; i < end; ++i) {
    const SphereValue& s = spheres[i];
    if (s.axis_ratio == 1.0f) {
      w.put("sphere{");
      w.vec(s.centre);
      w.put(',');
      w.number(s.radius);
      w.put("}\n");
    } else {
      // Flattened about its own centre: scale first, then move into place.
      w.put("sphere{0,");
      w.number(s.radius);
      w.put(" scale<1,");
      w.number(s.axis_ratio);
      w.put(",1>translate");
      w.vec(s.centre);
      w.put("}\n");
    }
  }
  w.finish();
}

void append_index(std::string& text, std::size_t value) {
  char buffer[max_number_chars];
  text.append(buffer, write_index(buffer, value));
}

void write_sphere_union(std::string& text, const std::vector<SphereValue>& spheres,
                        const char* material, int threads) {
  if (spheres.empty()) return;
  text += "union{\n";
  text += write_chunks(spheres.size(), threads, [&](std::size_t b, std::size_t e, std::string& t) {
    write_spheres(spheres, b, e, t);
  });
  text += "material{";
  text += material;
  // hollow everywhere: a ray through a non-hollow object inside a media container (mist,
  // a streetlight's cone) loses the media behind it, which paints every drop as a dark hole.
  text += "}\nno_shadow hollow\n}\n";
}

void write_streak_mesh(std::string& text, const std::vector<StreakValue>& streaks,
                       const StreakAtlasLayout& atlas, int threads) {
  if (streaks.empty()) return;
  const std::size_t n = streaks.size();
  text += "mesh2{\nvertex_vectors{";
  append_index(text, (4 * n));
  text += ",\n";
  text += write_chunks(n, threads, [&](std::size_t b, std::size_t e, std::string& t) {
    Writer w(t);
    w.reserve_more((e - b) * (12 * kNumberSpace + 16));
    for (std::size_t i = b; i < e; ++i) {
      for (const glm::vec3& c : streaks[i].corners) {
        w.vec(c);
        w.put(',');
      }
      w.put('\n');
    }
    w.finish();
  });
  // One uv quad per atlas cell, inset by half a texel so filtering never reads a neighbour.
  // Corners 0, 1 (trailing end) take the cell's top, 2, 3 (leading end) its bottom.
  const int cells = atlas.cells();
  text += "}\nuv_vectors{";
  append_index(text, 4 * static_cast<std::size_t>(cells));
  text += ",\n";
  const double width = atlas.width();
  const double height = atlas.height();
  for (int cell = 0; cell < cells; ++cell) {
    const int row = cell / atlas.shapes;
    const int column = cell % atlas.shapes;
    const double u0 = (column * atlas.cell_width + 0.5) / width;
    const double u1 = ((column + 1) * atlas.cell_width - 0.5) / width;
    const double v0 = (row * atlas.cell_height + 0.5) / height;
    const double v1 = ((row + 1) * atlas.cell_height - 0.5) / height;
    const double uv[4][2] = {{u0, v1}, {u1, v1}, {u1, v0}, {u0, v0}};
    for (const auto& corner : uv) {
      text += '<';
      append_number(text, corner[0]);
      text += ',';
      append_number(text, corner[1]);
      text += ">,";
    }
    text += '\n';
  }
  text += "}\nface_indices{";
  append_index(text, (2 * n));
  text += ",\n";
  text += write_chunks(n, threads, [&](std::size_t b, std::size_t e, std::string& t) {
    Writer w(t);
    w.reserve_more((e - b) * (6 * kNumberSpace + 16));
    for (std::size_t i = b; i < e; ++i) {
      const std::uint64_t v = 4 * i;
      w.put('<');
      w.index(v);
      w.put(',');
      w.index(v + 1);
      w.put(',');
      w.index(v + 2);
      w.put(">,<");
      w.index(v);
      w.put(',');
      w.index(v + 2);
      w.put(',');
      w.index(v + 3);
      w.put(">,\n");
    }
    w.finish();
  });
  text += "}\nuv_indices{";
  append_index(text, (2 * n));
  text += ",\n";
  text += write_chunks(n, threads, [&](std::size_t b, std::size_t e, std::string& t) {
    Writer w(t);
    w.reserve_more((e - b) * (6 * kNumberSpace + 16));
    for (std::size_t i = b; i < e; ++i) {
      const auto u = static_cast<std::uint64_t>(4 * streaks[i].cell);
      w.put('<');
      w.index(u);
      w.put(',');
      w.index(u + 1);
      w.put(',');
      w.index(u + 2);
      w.put(">,<");
      w.index(u);
      w.put(',');
      w.index(u + 2);
      w.put(',');
      w.index(u + 3);
      w.put(">,\n");
    }
    w.finish();
  });
  text += "}\ntexture{RT_StreakTexture}\nno_shadow hollow\n}\n";
}

void write_bolts(std::string& text, const std::vector<BoltValue>& bolts) {
  if (bolts.empty()) return;
  // Bolts are light, not rain: the rain mask leaves them out.
  text += "#if(RT_Mask=0)\n";
  for (const BoltValue& bolt : bolts) {
    if (bolt.segments.empty()) continue;
    text += "union{\n";
    for (const CylinderValue& c : bolt.segments) {
      text += "cylinder{<";
      append_number(text, c.start.x);
      text += ',';
      append_number(text, c.start.y);
      text += ',';
      append_number(text, c.start.z);
      text += ">,<";
      append_number(text, c.end.x);
      text += ',';
      append_number(text, c.end.y);
      text += ',';
      append_number(text, c.end.z);
      text += ">,";
      append_number(text, c.radius);
      text += "}\n";
    }
    text += "RT_BoltTexture(";
    append_number(text, bolt.brightness);
    text += ")\nno_shadow hollow\n}\n";
  }
  text += "#end\n";
}

}  // namespace

std::string frame_text(const FrameValues& values, const StreakAtlasLayout& atlas, int threads) {
  std::string text;
  text.reserve(1024);
  text += "// raintrace frame ";
  append_index(text, static_cast<std::size_t>(std::max(values.index, 0)));
  text += "\n#version 3.7;\n#declare RT_Flash=";
  append_number(text, values.flash);
  text += ";\n#declare RT_FlashPosition=<";
  append_number(text, values.flash_position.x);
  text += ',';
  append_number(text, values.flash_position.y);
  text += ',';
  append_number(text, values.flash_position.z);
  text += ">;\n#include \"scene.inc\"\n";
  write_sphere_union(text, values.drops, "RT_DropMaterial", threads);
  write_streak_mesh(text, values.streaks, atlas, threads);
  write_sphere_union(text, values.splashes, "RT_SplashMaterial", threads);
  write_bolts(text, values.bolts);
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
