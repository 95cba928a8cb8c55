#include "apps/fusion/measurement_merger.hpp"

#include <limits>

#include "apps/common/command_error.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/common/input_bytes.hpp"

namespace navfuse::apps {

// One input: its file, decoder and the measurements decoded from the current chunk.
struct MeasurementMerger::Stream final : frontends::DecodeSink {
  InputSpec spec;
  std::unique_ptr<InputBytes> bytes;
  std::unique_ptr<frontends::StreamDecoder> decoder;
  std::vector<Measurement> queue;  // capacity reused chunk after chunk
  std::size_t head = 0;
  std::uint16_t stream_id = 0;
  bool ended = false;
  std::array<std::uint64_t, static_cast<std::size_t>(MeasurementKind::kCount)>* decoded = nullptr;
  // A recorded input: its reads, the next one, the sequence number of the read the queue came
  // from, and the bytes read before format detection started decoding.
  const RecordedInput* recorded = nullptr;
  std::size_t next_read = 0;
  std::int64_t key = 0;
  std::vector<std::uint8_t> undecoded;

  void on_measurement(const Measurement& m) override {
    queue.push_back(m);
    header_of(queue.back()).stream_id = stream_id;
    ++(*decoded)[static_cast<std::size_t>(kind_of(m))];
  }
  bool has_data() const { return head < queue.size(); }
};

MeasurementMerger::MeasurementMerger(const std::vector<InputSpec>& inputs, const Options& options)
    : options_(options), chunk_(options.chunk_bytes) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    auto s = std::make_unique<Stream>();
    s->spec = inputs[i];
    s->bytes = std::make_unique<InputBytes>(s->spec);
    total_bytes_ += s->bytes->size_bytes();
    s->decoder = make_decoder(s->spec);
    s->stream_id = static_cast<std::uint16_t>(i);
    s->decoded = &decoded_;
    streams_.push_back(std::move(s));
  }
  start();
}

MeasurementMerger::MeasurementMerger(const Recording& recording, const Options& options)
    : options_(options) {
  options_.allow_truncated = true;
  for (std::size_t i = 0; i < recording.inputs.size(); ++i) {
    const RecordedInput& in = recording.inputs[i];
    auto s = std::make_unique<Stream>();
    s->spec.path = in.raw_path;
    s->spec.frontend = in.format.empty() ? nullptr : find_frontend(in.format);
    if (!in.format.empty() && s->spec.frontend == nullptr) {
      throw CommandError("recording: input '" + in.argument + "' has unknown format '" + in.format + "'");
    }
    s->bytes = std::make_unique<InputBytes>(s->spec);
    total_bytes_ += s->bytes->size_bytes();
    s->recorded = &in;
    s->stream_id = static_cast<std::uint16_t>(i);
    s->decoded = &decoded_;
    streams_.push_back(std::move(s));
  }
  start();
}

void MeasurementMerger::start() {
  for (std::size_t i = 0; i < streams_.size(); ++i) {
    refill(i);
    push_head(i);
  }
}

MeasurementMerger::~MeasurementMerger() = default;

void MeasurementMerger::refill(std::size_t i) {
  Stream& s = *streams_[i];
  if (s.has_data()) return;
  s.queue.clear();
  s.head = 0;
  if (s.recorded != nullptr) return refill_recorded(s);
  while (!s.has_data() && !s.ended) {
    const std::size_t n = s.bytes->read(chunk_);
    bytes_read_ += n;
    if (n > 0) {
      s.decoder->feed(std::span(chunk_.data(), n), s);
      continue;
    }
    end_of_input(s);
  }
}

// As run's input reader (apps/run/input_reader.cpp) did with each read: bytes before format
// detection are held, then decoded from where detection started, as one block with the read
// that completed detection; after that each read is decoded on its own.
void MeasurementMerger::refill_recorded(Stream& s) {
  const RecordedInput& in = *s.recorded;
  while (!s.has_data() && !s.ended) {
    if (!s.decoder && s.spec.frontend != nullptr && s.next_read == in.decode_after_reads) {
      s.decoder = s.spec.frontend->make_decoder();
      const std::uint64_t skipped = in.decode_from_offset;  // the held bytes start at offset 0
      if (skipped < s.undecoded.size()) {
        s.decoder->feed(std::span(s.undecoded).subspan(static_cast<std::size_t>(skipped)), s);
      }
      s.undecoded = {};
      s.key = in.decode_seq;
      continue;
    }
    if (s.next_read == in.reads.size()) {
      s.key = in.end_seq.value_or(std::numeric_limits<std::int64_t>::max());
      if (s.decoder) end_of_input(s);
      s.ended = true;
      continue;
    }
    const RecordedRead& read = in.reads[s.next_read++];
    chunk_.resize(read.length);
    std::size_t got = 0;
    while (got < chunk_.size()) {
      const std::size_t n = s.bytes->read(std::span(chunk_).subspan(got));
      if (n == 0) throw CommandError("recording: '" + s.spec.path + "' ends before its index does");
      got += n;
    }
    bytes_read_ += got;
    s.key = read.seq;
    if (s.decoder) {
      s.decoder->feed(chunk_, s);
    } else {
      s.undecoded.insert(s.undecoded.end(), chunk_.begin(), chunk_.end());
    }
  }
}

// End of an input: a frame still buffered by the framer was cut off.
void MeasurementMerger::end_of_input(Stream& s) {
  const std::uint64_t skipped_before = s.decoder->counters().skipped_bytes;
  s.decoder->finish(s);
  s.ended = true;
  const std::uint64_t cut = s.decoder->counters().skipped_bytes - skipped_before;
  if (cut > 0) {
    if (!options_.allow_truncated) {
      throw CommandError("input '" + s.spec.path + "' is truncated: its last " + std::to_string(cut) +
                         " bytes are an incomplete " + std::string(s.spec.frontend->format) +
                         " frame (--allow-truncated to replay it anyway)");
    }
    truncated_.push_back(s.spec.path);
  }
}

void MeasurementMerger::push_head(std::size_t i) {
  const Stream& s = *streams_[i];
  if (!s.has_data()) return;
  heads_.push({s.recorded != nullptr ? s.key : header_of(s.queue[s.head]).time_ns, i});
}

const Measurement* MeasurementMerger::next() {
  if (taken_from_) {
    const std::size_t i = *taken_from_;
    taken_from_.reset();
    refill(i);
    push_head(i);
  }
  if (heads_.empty()) return nullptr;
  const std::size_t i = heads_.top().input;
  heads_.pop();
  taken_from_ = i;
  Stream& s = *streams_[i];
  return &s.queue[s.head++];
}

std::vector<InputSummary> MeasurementMerger::input_summaries() const {
  std::vector<InputSummary> v;
  for (const auto& s : streams_) {
    v.push_back({s->spec.path, s->spec.frontend != nullptr ? std::string(s->spec.frontend->format) : "none",
                 s->decoder ? s->decoder->counters() : frontends::StreamCounters{}});
  }
  return v;
}

}  // namespace navfuse::apps
