#include "apps/run/input_endpoint.hpp"

#include <array>
#include <string_view>

#include "apps/common/command_error.hpp"
#include "apps/common/frontend_registry.hpp"

namespace navfuse::apps {
namespace {

constexpr std::array<std::string_view, 6> kSchemes = {"serial", "tcp", "tcp-listen", "udp", "udp-listen", "file"};

bool is_scheme(std::string_view word) {
  for (std::string_view s : kSchemes) {
    if (word == s) return true;
  }
  return false;
}

// A word before ':' that could only be meant as a format or scheme name (paths have '/' or '.').
bool looks_like_prefix(std::string_view word) {
  return !word.empty() && word.size() <= 12 && word.find_first_of("/.\\") == std::string_view::npos;
}

io::Uri to_uri(std::string_view text, const std::string& argument, const char* what) {
  const auto colon = text.find(':');
  const bool has_scheme = colon != std::string_view::npos && is_scheme(text.substr(0, colon));
  const std::string uri_text = has_scheme ? std::string(text) : "file:" + std::string(text);
  if (!has_scheme && colon != std::string_view::npos && looks_like_prefix(text.substr(0, colon))) {
    throw CommandError(std::string(what) + " '" + argument + "': unknown URI scheme '" +
                       std::string(text.substr(0, colon)) +
                       "' (expected serial:, tcp://, tcp-listen://, udp://, udp-listen:// or file:)");
  }
  try {
    return io::parse_uri(uri_text);
  } catch (const io::TransportError& e) {
    throw CommandError(std::string(what) + " '" + argument + "': " + e.what());
  }
}

}  // namespace

InputEndpoint parse_input_endpoint(const std::string& argument) {
  InputEndpoint in;
  in.text = argument;
  std::string_view rest = argument;
  const auto colon = rest.find(':');
  if (colon != std::string_view::npos) {
    const std::string_view prefix = rest.substr(0, colon);
    if (const auto* f = find_frontend(prefix)) {
      in.frontend = f;
      rest = rest.substr(colon + 1);
    } else if (!is_scheme(prefix) && looks_like_prefix(prefix)) {
      throw CommandError("--in '" + argument + "': unknown input format or scheme '" + std::string(prefix) +
                         "' (formats: " + known_formats() + "; schemes: serial, tcp, tcp-listen, udp, file)");
    }
  }
  if (rest.empty()) throw CommandError("--in '" + argument + "': missing URI");
  in.uri = to_uri(rest, argument, "--in");
  return in;
}

io::Uri parse_output_uri(const std::string& argument, const char* option) {
  if (argument.empty()) throw CommandError(std::string(option) + ": missing URI");
  return to_uri(argument, argument, option);
}

}  // namespace navfuse::apps
