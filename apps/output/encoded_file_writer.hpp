// A protocol stream written to a file (replay's --fe-out, --mip-out, --nmea-out): the bytes the protocol's
// epoch encoder appends at each epoch, at the encoder's default rates (the DESIGN.md contract),
// into an OutputFile. The same encoders drive run's device-emulating links (apps/run), so a
// file and a link carry the same bytes for the same epochs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps/output/fe_epoch_encoder.hpp"
#include "apps/output/mip_epoch_encoder.hpp"
#include "apps/output/nmea_epoch_encoder.hpp"
#include "apps/output/output_file.hpp"
#include "apps/output/pose_writer.hpp"

namespace navfuse::apps {

template <class Encoder>
class EncodedFileWriter final : public PoseWriter {
 public:
  explicit EncodedFileWriter(const std::string& path) : file_(path) { bytes_.reserve(4096); }
  void write(const OutputEpoch& epoch) override {
    bytes_.clear();
    encoder_.append(epoch, bytes_);
    file_.write(bytes_);
  }
  void commit() override { file_.commit(); }

 private:
  OutputFile file_;
  Encoder encoder_;                  // one per stream: its sequence numbers and rate state
  std::vector<std::uint8_t> bytes_;  // reused
};

using FeFileWriter = EncodedFileWriter<FeEpochEncoder>;    // --fe-out
using MipFileWriter = EncodedFileWriter<MipEpochEncoder>;  // --mip-out
using NmeaFileWriter = EncodedFileWriter<NmeaEpochEncoder>;  // --nmea-out

}  // namespace navfuse::apps
