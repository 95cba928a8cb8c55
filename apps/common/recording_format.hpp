// The raw-input recording of `navfuse run --record DIR`, read back by `navfuse replay
// --recording DIR` to give the live run's outputs again, byte for byte.
//
// DIR holds:
//   recording.json   what was recorded: each input's --in argument and its two files, the config
//                    file's copy (config.yaml) and the host time the run started
//   config.yaml      the run's --config, copied byte for byte
//   inN.raw          every byte input N delivered, in order (a plain log: `replay inN.raw` works)
//   inN.idx          one text line per event of input N, in order:
//                      R SEQ MONO_NS UTC_NS LENGTH   LENGTH bytes were read (host receive times:
//                                                    steady clock and UTC, ns)
//                      D SEQ FORMAT FROM_OFFSET      decoding started as FORMAT with the byte at
//                                                    FROM_OFFSET (earlier bytes were skipped by
//                                                    format detection), after read SEQ
//                                                    (SEQ -1: before any read, format given;
//                                                    after E: detected in the end's flush)
//                      E SEQ MONO_NS UTC_NS          the input ended; its decoder was flushed
//
// SEQ numbers one order over all inputs: the order in which the reads' measurements reached the
// filter (run queues a read's measurements as one block, under the recorder's lock, in SEQ
// order). Replaying reads in SEQ order, decoding each as run did, gives the filter the live
// run's exact sequence of measurements, and so the same outputs.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::apps {

inline constexpr std::string_view kRecordingManifest = "recording.json";
inline constexpr std::string_view kRecordingConfig = "config.yaml";
inline constexpr int kRecordingVersion = 1;

std::string recording_raw_name(std::size_t input);    // "in0.raw"
std::string recording_index_name(std::size_t input);  // "in0.idx"

// One read of an input.
struct RecordedRead {
  std::int64_t seq = 0;
  std::uint64_t length = 0;
};

struct RecordedInput {
  std::string argument;  // the --in argument of the live run
  std::string raw_path;
  std::vector<RecordedRead> reads;
  std::string format;                // "" when decoding never started (format never detected)
  std::size_t decode_after_reads = 0;  // decoding started once this many reads were in
  std::uint64_t decode_from_offset = 0;
  std::int64_t decode_seq = -1;             // the read at whose arrival decoding started
  std::optional<std::int64_t> end_seq;      // the input ended (absent: the run was cut off)
};

struct Recording {
  std::string dir;
  std::string config_path;  // the copy in DIR
  std::vector<RecordedInput> inputs;
};

// Reads DIR's manifest and indexes; throws CommandError naming the file and line on a missing
// file or a damaged line.
Recording read_recording(const std::string& dir);

// The manifest of a recording of `arguments` (the --in arguments) started at `utc_ns`.
void write_recording_manifest(const std::string& dir, const std::vector<std::string>& arguments, std::int64_t utc_ns);

// The index lines (written by run's recorder, parsed by read_recording).
void write_read_line(std::FILE* f, std::int64_t seq, std::int64_t mono_ns, std::int64_t utc_ns, std::uint64_t length);
void write_decode_line(std::FILE* f, std::int64_t seq, std::string_view format, std::uint64_t from_offset);
void write_end_line(std::FILE* f, std::int64_t seq, std::int64_t mono_ns, std::int64_t utc_ns);

}  // namespace navfuse::apps
