// LSF: leap-second forecast, output form (spec L1392-L1438; digest §4.10).
#include "frontends/nmea/record_fields.hpp"
#include "frontends/nmea/writer.hpp"
#include "frontends/unicore/messages.hpp"

namespace navfuse::frontends::unicore {
namespace {
constexpr std::size_t kLsfDataFields = 10;  // syntax L1406
}  // namespace

std::optional<Lsf> decode_lsf(const nmea::Fields& f) {
  if (f.data_count() != kLsfDataFields) return std::nullopt;
  Lsf m;
  if (!read(f[1], m.system) || !read(f[2], m.flag) || !read(f[3], m.tls_s) ||
      !read(f[4], m.tlsf_s) || !read(f[5], m.tot_s) || !read(f[6], m.wn) || !read(f[7], m.dn) ||
      !read(f[8], m.wnlsf) || !read(f[9], m.a0) || !read(f[10], m.a1)) {
    return std::nullopt;
  }
  return m;
}

bool encode(const Lsf& m, std::vector<std::uint8_t>& out) {
  nmea::SentenceWriter w;
  w.begin("LSF");
  w.add_uint(m.system);
  w.add_uint(m.flag);
  w.add_uint(m.tls_s);
  w.add_uint(m.tlsf_s);
  w.add_uint(m.tot_s);
  w.add_uint(m.wn);
  w.add_uint(m.dn);
  w.add_uint(m.wnlsf);
  w.add_int(m.a0);
  w.add_int(m.a1);
  return w.finish(out);
}

void append_fields(const Lsf& m, frontends::FrameRecord& r) {
  using nmea::put;
  put(r, "system", m.system);
  put(r, "flag", m.flag);
  put(r, "utc_tls_s", m.tls_s);
  put(r, "utc_tlsf_s", m.tlsf_s);
  put(r, "utc_tot_s", m.tot_s);
  put(r, "utc_wn", m.wn);
  put(r, "utc_dn", m.dn);
  put(r, "utc_wnlsf", m.wnlsf);
  put(r, "utc_a0", m.a0);  // units of 2^-30 s (L1421, digest §11 item 26)
  put(r, "utc_a1", m.a1);  // units of 2^-50 s/s
}

}  // namespace navfuse::frontends::unicore
