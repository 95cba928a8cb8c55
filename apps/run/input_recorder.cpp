#include "apps/run/input_recorder.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "apps/common/command_error.hpp"
#include "apps/common/recording_format.hpp"
#include "apps/run/run_log.hpp"

namespace navfuse::apps {
namespace {

namespace fs = std::filesystem;

// A crash or power cut loses at most this much of the recording (stdio buffers in between).
constexpr std::int64_t kFlushPeriodNs = 1'000'000'000;

std::int64_t utc_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::FILE* open_for_writing(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw CommandError("--record: cannot create '" + path + "': " + std::strerror(errno));
  return f;
}

}  // namespace

RunRecorder::RunRecorder(const std::string& dir, const std::string& config_path,
                         const std::vector<std::string>& arguments)
    : dir_(dir) {
  std::error_code ec;
  if (fs::exists(fs::path(dir) / kRecordingManifest, ec)) {
    throw CommandError("--record '" + dir + "' already holds a recording; give a new directory");
  }
  fs::create_directories(dir, ec);
  if (ec) throw CommandError("--record: cannot create '" + dir + "': " + ec.message());
  fs::copy_file(config_path, fs::path(dir) / kRecordingConfig, fs::copy_options::overwrite_existing, ec);
  if (ec) throw CommandError("--record: cannot copy '" + config_path + "' into '" + dir + "': " + ec.message());
  write_recording_manifest(dir, arguments, utc_ns());
}

std::unique_ptr<StreamRecorder> RunRecorder::open_stream(std::size_t index, const std::string& name) {
  return std::make_unique<StreamRecorder>(*this, (fs::path(dir_) / recording_raw_name(index)).string(),
                                          (fs::path(dir_) / recording_index_name(index)).string(), name);
}

StreamRecorder::StreamRecorder(RunRecorder& recorder, const std::string& raw_path, const std::string& index_path,
                               std::string name)
    : recorder_(recorder), name_(std::move(name)) {
  raw_ = open_for_writing(raw_path);
  index_ = open_for_writing(index_path);
  std::fprintf(index_, "# navfuse recording index v%d of '%s' (format: apps/common/recording_format.hpp)\n",
               kRecordingVersion, name_.c_str());
}

StreamRecorder::~StreamRecorder() {
  if (raw_ != nullptr) std::fclose(raw_);
  if (index_ != nullptr) std::fclose(index_);
}

std::unique_lock<std::mutex> StreamRecorder::read(std::span<const std::uint8_t> bytes, std::int64_t mono_ns) {
  std::unique_lock lock(recorder_.order_);
  last_seq_ = recorder_.next_seq_++;
  if (!failed_) {
    // Bytes first: an index line never describes bytes that are not in the raw file.
    check(std::fwrite(bytes.data(), 1, bytes.size(), raw_) == bytes.size());
    write_read_line(index_, last_seq_, mono_ns, utc_ns(), bytes.size());
    flush_every_second(mono_ns);
  }
  return lock;
}

void StreamRecorder::decoding(std::string_view format, std::uint64_t from_offset) {
  if (!failed_) write_decode_line(index_, last_seq_, format, from_offset);
}

std::unique_lock<std::mutex> StreamRecorder::end(std::int64_t mono_ns) {
  std::unique_lock lock(recorder_.order_);
  last_seq_ = recorder_.next_seq_++;
  if (!failed_) {
    write_end_line(index_, last_seq_, mono_ns, utc_ns());
    check(std::fflush(raw_) == 0 && std::fflush(index_) == 0);
  }
  return lock;
}

void StreamRecorder::flush_every_second(std::int64_t mono_ns) {
  if (mono_ns - last_flush_ns_ < kFlushPeriodNs) return;
  last_flush_ns_ = mono_ns;
  check(std::fflush(raw_) == 0 && std::fflush(index_) == 0);
}

void StreamRecorder::check(bool ok) {
  if (ok && std::ferror(index_) == 0) return;
  failed_ = true;
  log_event("input '" + name_ + "': recording failed (" + std::strerror(errno) + "); this input is no longer recorded");
}

}  // namespace navfuse::apps
