#include "apps/common/input_spec.hpp"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <vector>

#include "apps/common/command_error.hpp"
#include "apps/common/frontend_registry.hpp"
#include "apps/common/gps_week_inference.hpp"

namespace navfuse::apps {

InputSpec resolve_input(const std::string& argument) {
  InputSpec spec;
  spec.path = argument;
  // A prefix is a known format name before the first ':' (paths may contain ':' too, so an
  // unknown short word is only an error when it looks like a format, i.e. has no '/').
  const auto colon = argument.find(':');
  if (colon != std::string::npos && colon > 0) {
    const std::string prefix = argument.substr(0, colon);
    if (const auto* f = find_frontend(prefix)) {
      spec.frontend = f;
      spec.path = argument.substr(colon + 1);
    } else if (prefix.find('/') == std::string::npos && prefix.size() <= 8) {
      throw CommandError("unknown input format '" + prefix + "' in '" + argument + "' (known: " +
                         known_formats() + ")");
    }
  }
  std::shared_ptr<std::FILE> file(std::fopen(spec.path.c_str(), "rb"), [](std::FILE* f) {
    if (f != nullptr) std::fclose(f);
  });
  if (!file) throw CommandError("cannot open input '" + spec.path + "': " + std::strerror(errno));
  std::vector<std::uint8_t>& head = spec.head;
  head.resize(kProbeBytes);
  std::size_t got = 0;
  while (got < head.size()) {  // a pipe delivers in pieces
    const std::size_t n = std::fread(head.data() + got, 1, head.size() - got, file.get());
    if (n == 0) break;
    got += n;
  }
  head.resize(got);
  if (head.empty()) throw CommandError("input '" + spec.path + "' is empty");
  struct stat st {};
  if (::fstat(fileno(file.get()), &st) == 0 && !S_ISREG(st.st_mode)) spec.stream = std::move(file);
  if (!spec.frontend) {
    spec.frontend = detect_format(head);
    spec.format_detected = true;
    if (!spec.frontend) {
      throw CommandError("cannot detect the format of '" + spec.path + "': no valid frame of " +
                         known_formats() + " in its first " + std::to_string(head.size()) +
                         " bytes (give it as FORMAT:PATH)");
    }
  }
  return spec;
}

std::vector<InputSpec> resolve_inputs(const std::vector<std::string>& arguments,
                                      std::optional<std::int32_t> gps_week) {
  std::vector<InputSpec> specs;
  for (const auto& arg : arguments) specs.push_back(resolve_input(arg));
  for (InputSpec& spec : specs) {
    if (spec.frontend->make_decoder_in_week == nullptr) continue;
    spec.gps_week = gps_week ? gps_week : infer_gps_week(spec, specs);
    if (!spec.gps_week) {
      throw CommandError("input '" + spec.path + "' (" + std::string(spec.frontend->format) +
                         ") is timed in seconds of week: give the GPS week with --gps-week W, or "
                         "an input with GPS time (e.g. rtklib:FILE.pos) to take it from");
    }
  }
  return specs;
}

std::unique_ptr<frontends::StreamDecoder> make_decoder(const InputSpec& spec) {
  if (spec.gps_week && spec.frontend->make_decoder_in_week != nullptr) {
    return spec.frontend->make_decoder_in_week(*spec.gps_week);
  }
  return spec.frontend->make_decoder();
}

}  // namespace navfuse::apps
