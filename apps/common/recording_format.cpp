#include "apps/common/recording_format.hpp"

#include <cinttypes>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void damaged(const std::string& path, std::size_t line, const std::string& why) {
  throw CommandError("recording index '" + path + "' line " + std::to_string(line) + ": " + why);
}

void read_index(const std::string& path, RecordedInput& in) {
  std::ifstream file(path);
  if (!file) throw CommandError("recording: cannot open index '" + path + "'");
  std::string line;
  std::size_t number = 0;
  std::int64_t last_seq = -1;
  bool decoding = false;
  while (std::getline(file, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    char tag = 0;
    std::int64_t seq = 0;
    ss >> tag >> seq;
    if (!ss) damaged(path, number, "expected a tag and a sequence number");
    if (in.end_seq && tag != 'D') damaged(path, number, "event after the end of the input");
    if (tag == 'R') {
      std::int64_t mono_ns = 0, utc_ns = 0;
      std::uint64_t length = 0;
      ss >> mono_ns >> utc_ns >> length;
      if (!ss || length == 0) damaged(path, number, "a read needs MONO_NS UTC_NS LENGTH > 0");
      if (seq <= last_seq) damaged(path, number, "sequence numbers must increase");
      last_seq = seq;
      in.reads.push_back({seq, length});
    } else if (tag == 'D') {
      std::uint64_t from = 0;
      ss >> in.format >> from;
      if (!ss || decoding) damaged(path, number, decoding ? "decoding started twice" : "a decode needs FORMAT FROM_OFFSET");
      decoding = true;
      in.decode_after_reads = in.reads.size();
      in.decode_from_offset = from;
      in.decode_seq = seq;
    } else if (tag == 'E') {
      if (seq <= last_seq) damaged(path, number, "sequence numbers must increase");
      in.end_seq = seq;
    } else {
      damaged(path, number, std::string("unknown tag '") + tag + "'");
    }
  }
  std::uint64_t bytes = 0;
  for (const RecordedRead& r : in.reads) bytes += r.length;
  std::error_code ec;
  const auto size = fs::file_size(in.raw_path, ec);
  if (ec) throw CommandError("recording: cannot open '" + in.raw_path + "': " + ec.message());
  // The raw file can be longer than its index (the index line is written after the bytes), never shorter.
  if (size < bytes) {
    throw CommandError("recording: '" + in.raw_path + "' holds " + std::to_string(size) + " bytes, its index " +
                       std::to_string(bytes));
  }
  if (decoding && in.decode_from_offset > bytes) damaged(path, number, "decoding starts beyond the recorded bytes");
}

}  // namespace

std::string recording_raw_name(std::size_t input) { return "in" + std::to_string(input) + ".raw"; }
std::string recording_index_name(std::size_t input) { return "in" + std::to_string(input) + ".idx"; }

void write_recording_manifest(const std::string& dir, const std::vector<std::string>& arguments, std::int64_t utc_ns) {
  nlohmann::ordered_json j;
  j["navfuse_recording"] = kRecordingVersion;
  j["started_utc_ns"] = utc_ns;
  j["config"] = kRecordingConfig;
  j["inputs"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    j["inputs"].push_back({{"argument", arguments[i]}, {"raw", recording_raw_name(i)}, {"index", recording_index_name(i)}});
  }
  const std::string path = (fs::path(dir) / kRecordingManifest).string();
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out) throw CommandError("--record: cannot write '" + path + "'");
}

Recording read_recording(const std::string& dir) {
  const std::string manifest = (fs::path(dir) / kRecordingManifest).string();
  std::ifstream file(manifest);
  if (!file) throw CommandError("--recording '" + dir + "': no " + std::string(kRecordingManifest) + " (not a navfuse run --record directory?)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& e) {
    throw CommandError("recording: '" + manifest + "' is not valid JSON: " + e.what());
  }
  if (j.value("navfuse_recording", 0) != kRecordingVersion || !j.contains("inputs") || !j["inputs"].is_array()) {
    throw CommandError("recording: '" + manifest + "' is not a version " + std::to_string(kRecordingVersion) +
                       " navfuse recording manifest");
  }
  Recording r;
  r.dir = dir;
  r.config_path = (fs::path(dir) / j.value("config", std::string(kRecordingConfig))).string();
  for (const auto& in : j["inputs"]) {
    RecordedInput ri;
    ri.argument = in.value("argument", "");
    ri.raw_path = (fs::path(dir) / in.value("raw", "")).string();
    read_index((fs::path(dir) / in.value("index", "")).string(), ri);
    r.inputs.push_back(std::move(ri));
  }
  if (r.inputs.empty()) throw CommandError("recording: '" + manifest + "' lists no input");
  return r;
}

void write_read_line(std::FILE* f, std::int64_t seq, std::int64_t mono_ns, std::int64_t utc_ns, std::uint64_t length) {
  std::fprintf(f, "R %" PRId64 " %" PRId64 " %" PRId64 " %" PRIu64 "\n", seq, mono_ns, utc_ns, length);
}

void write_decode_line(std::FILE* f, std::int64_t seq, std::string_view format, std::uint64_t from_offset) {
  std::fprintf(f, "D %" PRId64 " %.*s %" PRIu64 "\n", seq, static_cast<int>(format.size()), format.data(), from_offset);
}

void write_end_line(std::FILE* f, std::int64_t seq, std::int64_t mono_ns, std::int64_t utc_ns) {
  std::fprintf(f, "E %" PRId64 " %" PRId64 " %" PRId64 "\n", seq, mono_ns, utc_ns);
}

}  // namespace navfuse::apps
