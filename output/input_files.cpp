#include "output/input_files.h"

#include <chrono>

#include "output/image_check.h"

namespace raintrace::output {

namespace fs = std::filesystem;

namespace {

std::optional<std::int64_t> mtime_ns(const fs::path& path) {
  std::error_code error;
  const auto t = fs::last_write_time(path, error);
  if (error) return std::nullopt;
  return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

}  // namespace

std::optional<InputFileRecord> record_input_file(const fs::path& dir, const std::string& relative) {
  const auto time = mtime_ns(dir / relative);
  const auto facts = time ? file_facts(dir / relative) : std::nullopt;
  if (!facts) return std::nullopt;
  return InputFileRecord{relative, facts->size, *time, facts->hash};
}

InputFileCheck check_input_file(const fs::path& dir, InputFileRecord& record) {
  const fs::path path = dir / record.path;
  std::error_code error;
  const auto size = fs::file_size(path, error);
  const auto time = mtime_ns(path);
  if (error || !time) return InputFileCheck::missing;
  if (size == record.size && *time == record.mtime_ns) return InputFileCheck::same;
  auto now = record_input_file(dir, record.path);
  if (!now) return InputFileCheck::missing;
  const bool same_bytes = now->size == record.size && now->hash == record.hash;
  now->by_hand = record.by_hand || !same_bytes;
  record = *now;
  return same_bytes ? InputFileCheck::touched : InputFileCheck::edited;
}

}  // namespace raintrace::output
