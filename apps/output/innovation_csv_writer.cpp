#include "apps/output/innovation_csv_writer.hpp"

#include <optional>

#include "apps/output/csv_fields.hpp"

namespace navfuse::apps {

InnovationCsvWriter::InnovationCsvWriter(const std::string& path) : file_(path) {
  file_.write(std::string_view("time_s,kind,fix,result,rows,nis,r0,r1,r2,s0,s1,s2\n"));
  row_.reserve(256);
}

namespace {

std::optional<GnssFixType> fix_of(const Measurement& m) {
  if (const auto* p = std::get_if<GnssPosition>(&m)) return p->fix;
  if (const auto* v = std::get_if<GnssVelocity>(&m)) return v->fix;
  return std::nullopt;
}

}  // namespace

void InnovationCsvWriter::write(const Measurement& m, const filter::FuseResult& result) {
  row_.clear();
  csv::append_time(row_, header_of(m).time_ns);
  row_ += ',';
  row_ += to_string(kind_of(m));
  row_ += ',';
  if (const auto fix = fix_of(m)) row_ += to_string(*fix);
  row_ += ',';
  row_ += result.used ? std::string_view("used") : filter::to_string(result.reason);
  row_ += ',';
  row_ += static_cast<char>('0' + result.rows);
  csv::append_fixed(row_, result.nis, 4);
  for (std::size_t i = 0; i < 3; ++i) csv::append_fixed(row_, result.residual[i], 5);
  for (std::size_t i = 0; i < 3; ++i) csv::append_fixed(row_, result.innovation_std[i], 5);
  row_ += '\n';
  file_.write(row_);
}

}  // namespace navfuse::apps
