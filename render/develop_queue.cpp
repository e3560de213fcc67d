// The develop thread and the develop of one frame.
#include "render/develop_queue.h"

#include <fmt/core.h>
#include <chrono>
#include <exception>
#include <system_error>

#include "output/image_check.h"
#include "render/povray_command.h"

namespace raintrace::render {

DevelopTarget develop_target(const output::Manifest& m) {
  DevelopTarget t;
  t.settings = m.develop.settings;
  t.fov_deg = m.develop.fov_deg;
  t.aperture_m = m.develop.aperture_m;
  t.seed = m.identity.seed;
  t.width = m.identity.width;
  t.height = m.identity.height;
  t.digits = output::frame_digits(m);
  return t;
}

std::unique_ptr<film::DisplayTransform> prepare_develop(output::FolderState& folder) {
  auto display = std::make_unique<film::DisplayTransform>();
  const output::Manifest& m = folder.manifest();
  folder.set_develop_hash(
      output::develop_hash(m.develop, m.identity.seed,
                           display->response(m.develop.settings.view, m.develop.settings.look)));
  return display;
}

DevelopResult develop_frame(const std::filesystem::path& out_dir, int frame,
                            const DevelopTarget& target, const film::DisplayTransform& display) {
  const auto start = std::chrono::steady_clock::now();
  DevelopResult result;
  result.frame = frame;
  const auto temp = out_dir / temp_developed_name(frame, target.digits);
  try {
    std::filesystem::create_directories(temp.parent_path());
    film::develop_file(out_dir / final_image_name(Pass::image, frame, target.digits), temp,
                       target.settings,
                       {.fov_deg = target.fov_deg,
                        .seed = target.seed,
                        .frame = frame,
                        .aperture_m = target.aperture_m},
                       display);
    std::string why;
    if (!output::image_is_complete(temp, target.width, target.height, &why)) {
      throw std::runtime_error(
          fmt::format("{}: {}", temp_developed_name(frame, target.digits), why));
    }
    std::filesystem::rename(temp, out_dir / developed_image_name(frame, target.digits));
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

DevelopQueue::DevelopQueue(std::filesystem::path out_dir, DevelopTarget target,
                           const film::DisplayTransform& display, const std::atomic<bool>* stop)
    : m_out{std::move(out_dir)},
      m_target{target},
      m_display{display},
      m_stop{stop},
      m_thread{[this] { work(); }} {}

DevelopQueue::~DevelopQueue() {
  {
    const std::lock_guard lock{m_mutex};
    m_closing = true;
  }
  m_wake.notify_all();
  m_thread.join();
}

void DevelopQueue::submit(int frame, bool only) {
  {
    const std::lock_guard lock{m_mutex};
    m_queue.emplace_back(frame, only);
  }
  m_wake.notify_one();
}

std::vector<DevelopResult> DevelopQueue::take() {
  const std::lock_guard lock{m_mutex};
  std::vector<DevelopResult> out;
  out.swap(m_done);
  return out;
}

bool DevelopQueue::idle() const {
  const std::lock_guard lock{m_mutex};
  return !m_busy && (m_queue.empty() || stopped());
}

void DevelopQueue::work() {
  std::unique_lock lock{m_mutex};
  for (;;) {
    // A stop request is seen within this wait's timeout: the signal handler cannot notify.
    m_wake.wait_for(lock, std::chrono::milliseconds(50),
                    [this] { return m_closing || !m_queue.empty(); });
    if (m_closing || stopped()) return;
    if (m_queue.empty()) continue;
    const auto [frame, only] = m_queue.front();
    m_queue.pop_front();
    m_busy = true;
    lock.unlock();
    DevelopResult result = develop_frame(m_out, frame, m_target, m_display);
    result.only = only;
    lock.lock();
    m_done.push_back(std::move(result));
    m_busy = false;
  }
}

}  // namespace raintrace::render
