// Develop in a render run, without POV-Ray: EXRs written here stand in for rendered frames.
#include "render/develop_queue.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "output/image_check.h"
#include "render/povray_command.h"
#include "render/test_folder.h"

namespace raintrace::render {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 48;
constexpr int kHeight = 27;

/// Writes images/frame_NNNN.exr: a half-float ramp from black to a lamp at 300, different for
/// every frame.
void write_exr(const fs::path& out, int frame) {
  std::vector<float> px;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float v = 300.0f * float(x * y + frame) / float(kWidth * kHeight);
      px.insert(px.end(), {v, 0.5f * v, 0.25f * v});
    }
  }
  const fs::path path = out / final_image_name(Pass::image, frame);
  fs::create_directories(path.parent_path());
  auto file = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(file);
  ASSERT_TRUE(file->open(path.string(), OIIO::ImageSpec(kWidth, kHeight, 3, OIIO::TypeDesc::HALF)));
  ASSERT_TRUE(file->write_image(OIIO::TypeDesc::FLOAT, px.data()));
  file->close();
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in{path, std::ios::binary};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

DevelopTarget target() {
  DevelopTarget t;
  t.width = kWidth;
  t.height = kHeight;
  t.seed = 3;
  return t;
}

const film::DisplayTransform& filmic() {
  static const film::DisplayTransform transform;
  return transform;
}

TEST(DevelopFrame, WritesAVerifiedPngAtItsFinalNameAndNothingElse) {
  const auto out = testing::fresh_test_dir("develop_one");
  write_exr(out, 4);
  const DevelopResult r = develop_frame(out, 4, target(), filmic());
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.frame, 4);
  EXPECT_TRUE(output::image_is_complete(out / developed_image_name(4), kWidth, kHeight));
  EXPECT_TRUE(fs::is_empty(out / temp_dir_name()));
  // The very pixels film::develop_file gives for this frame (seed 3, frame 4).
  film::develop_file(out / final_image_name(Pass::image, 4), out / "expected.png",
                     target().settings, {60.0, 3, 4}, filmic());
  EXPECT_TRUE(bytes_of(out / developed_image_name(4)) == bytes_of(out / "expected.png"));
}

TEST(DevelopFrame, ABrokenExrIsAFailureWithItsReasonAndLeavesNoPng) {
  const auto out = testing::fresh_test_dir("develop_broken");
  write_exr(out, 1);
  const fs::path exr = out / final_image_name(Pass::image, 1);
  fs::resize_file(exr, fs::file_size(exr) / 2);
  const DevelopResult r = develop_frame(out, 1, target(), filmic());
  EXPECT_NE(r.error.find("frame_0001.exr"), std::string::npos) << r.error;
  EXPECT_FALSE(fs::exists(out / developed_image_name(1)));
  EXPECT_TRUE(fs::is_empty(out / temp_dir_name()));
  // Another frame's size is rejected before it reaches its final name.
  write_exr(out, 2);
  DevelopTarget wrong = target();
  wrong.width = 64;
  const DevelopResult sized = develop_frame(out, 2, wrong, filmic());
  EXPECT_FALSE(sized.error.empty());
  EXPECT_FALSE(fs::exists(out / developed_image_name(2)));
}

std::vector<DevelopResult> wait_for(DevelopQueue& queue, std::size_t count) {
  std::vector<DevelopResult> all;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (all.size() < count && std::chrono::steady_clock::now() < deadline) {
    for (auto& r : queue.take()) all.push_back(std::move(r));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return all;
}

TEST(DevelopQueue, DevelopsWhatIsSubmittedInOrderOnItsOwnThread) {
  const auto out = testing::fresh_test_dir("develop_queue");
  for (int f = 1; f <= 5; ++f) write_exr(out, f);
  DevelopQueue queue{out, target(), filmic()};
  for (int f = 1; f <= 5; ++f) queue.submit(f, f == 3);
  const auto results = wait_for(queue, 5);
  ASSERT_EQ(results.size(), 5U);
  for (int f = 1; f <= 5; ++f) {
    EXPECT_EQ(results[std::size_t(f - 1)].frame, f);
    EXPECT_EQ(results[std::size_t(f - 1)].only, f == 3);
    EXPECT_TRUE(results[std::size_t(f - 1)].error.empty());
  }
  EXPECT_TRUE(queue.idle());
}

TEST(DevelopQueue, AStopFinishesTheFrameInHandAndLeavesTheRest) {
  const auto out = testing::fresh_test_dir("develop_stop");
  for (int f = 1; f <= 40; ++f) write_exr(out, f);
  std::atomic<bool> stop{false};
  DevelopQueue queue{out, target(), filmic(), &stop};
  for (int f = 1; f <= 40; ++f) queue.submit(f);
  const auto first = wait_for(queue, 1);
  stop.store(true);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!queue.idle() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_TRUE(queue.idle());
  const std::size_t developed = first.size() + queue.take().size();
  EXPECT_GE(developed, 1U);
  EXPECT_LT(developed, 40U);
  // What is at a final name is whole; the frames left have no PNG at all.
  int pngs = 0;
  for (int f = 1; f <= 40; ++f) {
    if (!fs::exists(out / developed_image_name(f))) continue;
    ++pngs;
    EXPECT_TRUE(output::image_is_complete(out / developed_image_name(f), kWidth, kHeight)) << f;
  }
  EXPECT_EQ(std::size_t(pngs), developed);
}

}  // namespace
}  // namespace raintrace::render
