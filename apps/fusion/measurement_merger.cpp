#include "apps/fusion/measurement_merger.hpp"

#include "apps/common/command_error.hpp"
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
  while (!s.has_data() && !s.ended) {
    const std::size_t n = s.bytes->read(chunk_);
    bytes_read_ += n;
    if (n > 0) {
      s.decoder->feed(std::span(chunk_.data(), n), s);
      continue;
    }
    // End of file: a frame still buffered by the framer was cut off.
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
}

void MeasurementMerger::push_head(std::size_t i) {
  const Stream& s = *streams_[i];
  if (s.has_data()) heads_.push({header_of(s.queue[s.head]).time_ns, i});
}

bool MeasurementMerger::next(Measurement& out) {
  if (heads_.empty()) return false;
  const std::size_t i = heads_.top().input;
  heads_.pop();
  Stream& s = *streams_[i];
  out = s.queue[s.head++];
  refill(i);
  push_head(i);
  return true;
}

std::vector<InputSummary> MeasurementMerger::input_summaries() const {
  std::vector<InputSummary> v;
  for (const auto& s : streams_) v.push_back({s->spec.path, std::string(s->spec.frontend->format), s->decoder->counters()});
  return v;
}

}  // namespace navfuse::apps
