#include "apps/decode/decode_command.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/command_error.hpp"
#include "apps/common/command_help.hpp"
#include "apps/common/empty_run.hpp"
#include "apps/common/input_bytes.hpp"
#include "apps/common/interrupt_signals.hpp"
#include "apps/common/gps_week_option.hpp"
#include "apps/common/input_spec.hpp"
#include "apps/common/measurement_fields.hpp"
#include "apps/common/summary.hpp"
#include "apps/output/output_file.hpp"
#include "apps/output/output_paths.hpp"

namespace navfuse::apps {
namespace {

struct DecodeOptions {
  std::string input;
  std::optional<std::int32_t> gps_week;
  std::string format = "csv";
  std::string out_path;  // empty: stdout
  std::string summary_json;
  bool quiet = false;
  bool allow_empty = false;
};

// CSV in long ("tidy") form, one row per field, because frames of different types have
// different fields: record,offset,protocol,name,field,value.
void write_csv_field(std::ostream& os, const std::string& value) {
  if (value.find_first_of(",\"\n") == std::string::npos) {
    os << value;
    return;
  }
  os << '"';
  for (char c : value) {
    if (c == '"') os << '"';
    os << c;
  }
  os << '"';
}

std::string value_text(const frontends::FieldValue& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::string>) {
          return x;
        } else if constexpr (std::is_same_v<T, double>) {
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.17g", x);
          return buf;
        } else {
          return std::to_string(x);
        }
      },
      v);
}

nlohmann::ordered_json value_json(const frontends::FieldValue& v) {
  return std::visit([](const auto& x) -> nlohmann::ordered_json {
    using T = std::decay_t<decltype(x)>;
    if constexpr (std::is_same_v<T, double>) {
      if (!std::isfinite(x)) return nullptr;  // JSON has no NaN
    }
    return x;
  }, v);
}

class PrintingSink final : public frontends::DecodeSink {
 public:
  PrintingSink(std::ostream& os, bool jsonl, Summary& summary) : os_(os), jsonl_(jsonl), summary_(summary) {
    if (!jsonl_) os_ << "record,offset,protocol,name,field,value\n";
  }
  bool wants_frames() const override { return true; }
  void on_frame(const frontends::FrameRecord& f) override {
    last_offset_ = f.offset;
    emit("frame", f);
  }
  void on_measurement(const Measurement& m) override {
    ++summary_.kind(kind_of(m)).decoded;
    record_.protocol = protocol_;
    record_.offset = last_offset_;
    measurement_to_record(m, record_);
    emit("measurement", record_);
  }
  std::string_view protocol_;

 private:
  void emit(const char* type, const frontends::FrameRecord& r) {
    if (jsonl_) {
      nlohmann::ordered_json j;
      j["record"] = type;
      j["offset"] = r.offset;
      j["protocol"] = r.protocol;
      j["name"] = r.name;
      nlohmann::ordered_json fields = nlohmann::ordered_json::object();
      for (const auto& [k, v] : r.fields) fields[k] = value_json(v);
      j["fields"] = fields;
      os_ << j.dump() << '\n';
      return;
    }
    for (const auto& [k, v] : r.fields) {
      os_ << type << ',' << r.offset << ',' << r.protocol << ',';
      write_csv_field(os_, r.name);
      os_ << ',';
      write_csv_field(os_, k);
      os_ << ',';
      write_csv_field(os_, value_text(v));
      os_ << '\n';
    }
  }

  std::ostream& os_;
  bool jsonl_;
  Summary& summary_;
  frontends::FrameRecord record_;
  std::uint64_t last_offset_ = 0;
};

int run_decode(const DecodeOptions& opt) {
  const InputSpec spec = resolve_inputs({opt.input}, opt.gps_week).front();
  InputBytes in(spec);

  check_output_paths({spec.path}, {{"--out", opt.out_path}, {"--summary-json", opt.summary_json}});
  // The records gather in `text` and go out after each input chunk through an OutputFile (a
  // regular file -o appears complete or not at all; standard output, a device or a FIFO is
  // streamed to, and a stalled reader cannot hold off Ctrl-C).
  OutputFile out(opt.out_path.empty() ? "-" : opt.out_path);
  std::ostringstream text;
  const auto drain = [&] {
    out.write(text.view());
    text.str({});
  };

  const InterruptSignals signals;
  Summary summary;
  auto decoder = make_decoder(spec);
  PrintingSink sink(text, opt.format == "jsonl", summary);
  sink.protocol_ = spec.frontend->format;
  // 256 KiB of input gives a few MB of records to hold before they go out.
  std::vector<std::uint8_t> chunk(1 << 18);
  while (const std::size_t n = in.read(chunk)) {
    decoder->feed(std::span(chunk.data(), n), sink);
    drain();
    if ((summary.interrupted_by = InterruptSignals::received().load(std::memory_order_relaxed)) != 0) break;
  }
  // Also after a signal: what is left of the stream is counted (skipped), every record is whole.
  decoder->finish(sink);
  drain();
  out.commit();

  summary.inputs.push_back({spec.path, std::string(spec.frontend->format), decoder->counters()});
  if (!opt.summary_json.empty()) write_json_file(opt.summary_json, summary.to_json(/*decode_only=*/true));
  const bool interrupted = summary.interrupted_by != 0;
  if ((!opt.out_path.empty() && !opt.quiet) || interrupted) summary.print(std::cerr, /*decode_only=*/true);
  if (interrupted) return interrupted_exit_code(summary.interrupted_by);
  if (std::string reason = no_frame_reason(summary.inputs.front()); !reason.empty()) {
    return nothing_useful("decode", reason, opt.allow_empty);
  }
  return 0;
}

}  // namespace

void add_decode_command(CLI::App& root, int& exit_code) {
  auto opt = std::make_shared<DecodeOptions>();
  CLI::App* sub = root.add_subcommand("decode", "Decode a log: every frame and the normalised measurements");
  sub->add_option("INPUT", opt->input, "[FORMAT:]PATH; FORMAT one of fe, mip, vn, unicore, rtklib, imutxt (detected when "
                                          "omitted)")
      ->required();
  add_gps_week_option(sub, opt->gps_week);
  sub->add_option("--format", opt->format, "Output format")->check(CLI::IsMember({"csv", "jsonl"}));
  sub->add_option("-o,--out", opt->out_path, "Write the records to this file instead of stdout");
  sub->add_option("--summary-json", opt->summary_json, "Write the counters as JSON to this file");
  add_quiet_flag(sub, opt->quiet, "counters on stderr with -o");
  add_examples(sub, {{"every frame and measurement of the demo VN-300 log, as JSON lines",
                      "navfuse decode data/demo/vn300.vnb --format jsonl | head"},
                     {"a MIP log (format given) to a CSV file, the counters as JSON",
                      "navfuse decode mip:data/demo/cv7.mip -o cv7.csv --summary-json cv7.json"}});
  sub->add_flag("--allow-empty", opt->allow_empty, kAllowEmptyHelp);
  sub->callback([opt, &exit_code] { exit_code = run_decode(*opt); });
}

}  // namespace navfuse::apps
