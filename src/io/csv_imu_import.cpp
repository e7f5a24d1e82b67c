#include "imu_lab/io/csv_imu_import.h"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <cmath>
#include <limits>
#include <sstream>
#include <string_view>

#include "imu_lab/common/config_error.h"
#include "imu_lab/common/stamps.h"
#include "imu_lab/identify/units.h"
#include "imu_lab/io/csv_header_inference.h"

namespace imu_lab {
namespace io {
namespace {

// ROS stamps are unsigned 32-bit seconds, and rosbag refuses time zero.
constexpr std::int64_t kMaxRosStamp_ns = 4294967295LL * 1000000000LL + 999999999LL;

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\r')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
  return text;
}

std::vector<std::string_view> split(std::string_view line, char delimiter) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(delimiter, start);
    fields.push_back(trim(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
    if (end == std::string_view::npos) return fields;
    start = end + 1;
  }
}

// The cell as a double; an explanation instead when it is not a finite number.
struct Number {
  double value = 0.0;
  std::string problem;  // empty: ok
};

Number parse_number(std::string_view cell, bool decimal_comma) {
  std::string text(cell);
  if (decimal_comma) std::replace(text.begin(), text.end(), ',', '.');
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  Number number;
  if (cell.empty()) {
    number.problem = "is empty";
    return number;
  }
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number.value);
  if (error != std::errc() || end != digits.data() + digits.size()) {
    number.problem = "'" + std::string(cell) + "' is not a number";
  } else if (!std::isfinite(number.value)) {
    number.problem = "'" + std::string(cell) + "' is not a finite number";
  }
  return number;
}

bool is_missing_reading(std::string_view cell) {
  if (cell.empty()) return true;
  std::string lower(cell);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower == "nan" || lower == "-nan" || lower == "+nan";
}

int unit_exponent_to_ns(TimeUnit unit) {
  switch (unit) {
    case TimeUnit::kSecond: return 9;
    case TimeUnit::kMillisecond: return 6;
    case TimeUnit::kMicrosecond: return 3;
    case TimeUnit::kNanosecond: return 0;
  }
  return 0;
}

bool is_column_number(const std::string& spec) {
  return !spec.empty() && std::all_of(spec.begin(), spec.end(), [](unsigned char c) { return std::isdigit(c); });
}

// Column spec -> 0-based index into a row.
std::size_t resolve_column(const std::string& source, const std::string& spec, const std::string& role,
                           const std::vector<std::string>& header, bool has_header) {
  if (spec.empty()) throw ConfigError(source, role, "no column given");
  if (is_column_number(spec)) {
    if (spec.size() > 6) throw ConfigError(source, role, "column number '" + spec + "' is too large");
    const unsigned long number = std::stoul(spec);
    if (number < 1) throw ConfigError(source, role, "column numbers start at 1, got '" + spec + "'");
    return number - 1;
  }
  if (!has_header) {
    throw ConfigError(source, role,
                      "column '" + spec + "' is a name, but the file is read without a header line: give its number");
  }
  const auto found = std::find(header.begin(), header.end(), spec);
  if (found == header.end()) {
    std::string names;
    for (const auto& name : header) names += (names.empty() ? "" : ", ") + name;
    throw ConfigError(source, role, "no column '" + spec + "' in the header (it has: " + names + ")");
  }
  if (std::find(found + 1, header.end(), spec) != header.end()) {
    throw ConfigError(source, role, "the header names '" + spec + "' twice: give its number instead");
  }
  return static_cast<std::size_t>(found - header.begin());
}

struct ColumnIndices {
  std::size_t time = 0;
  std::array<std::size_t, 3> gyro{}, accel{};
  std::optional<std::size_t> temperature;
  std::size_t highest = 0;
};

ColumnIndices resolve_columns(const std::string& source, const CsvImportOptions& options,
                              const std::vector<std::string>& header) {
  ColumnIndices columns;
  columns.time = resolve_column(source, options.time_column, "time_column", header, options.has_header);
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    columns.gyro[i] = resolve_column(source, options.gyro_columns[i], std::string("gyro_columns.") + axes[i], header,
                                     options.has_header);
    columns.accel[i] = resolve_column(source, options.accel_columns[i], std::string("accel_columns.") + axes[i], header,
                                      options.has_header);
  }
  if (!options.temperature_column.empty()) {
    columns.temperature =
        resolve_column(source, options.temperature_column, "temperature_column", header, options.has_header);
  }
  columns.highest = std::max({columns.time, columns.gyro[0], columns.gyro[1], columns.gyro[2], columns.accel[0],
                              columns.accel[1], columns.accel[2], columns.temperature.value_or(0)});
  return columns;
}

std::string column_label(const std::vector<std::string>& header, std::size_t index) {
  std::string label = "column " + std::to_string(index + 1);
  if (index < header.size() && !header[index].empty()) label += " (" + header[index] + ")";
  return label;
}

void check_options(const CsvImportOptions& options, const std::string& source) {
  if (options.decimal_comma && options.delimiter == ',') {
    throw ConfigError(source, "decimal_comma", "needs a delimiter other than ',' (e.g. ';')");
  }
  if (options.delimiter == '\n' || options.delimiter == '"' || options.delimiter == '#' ||
      std::isdigit(static_cast<unsigned char>(options.delimiter))) {
    throw ConfigError(source, "delimiter", "cannot be a newline, quote, '#' or digit");
  }
}

// One of a few accepted names -> its value; anything else -> ConfigError listing them.
template <class Value>
Value parse_name(const std::string& name, const std::string& source, const std::string& key, const std::string& what,
                 std::initializer_list<std::pair<const char*, Value>> accepted) {
  std::string names;
  std::size_t index = 0;
  for (const auto& [text, value] : accepted) {
    if (name == text) return value;
    names += std::string(index == 0 ? "" : index + 1 == accepted.size() ? " or " : ", ") + text;
    ++index;
  }
  throw ConfigError(source, key, "unknown " + what + " '" + name + "' (" + names + ")");
}

enum class LineRead { kLine, kTooLong, kEnd };

// One line without its '\n', at most kMaxLineBytes of it kept: a longer one is read to its end
// and reported, so one enormous line cannot fill the memory.
LineRead read_bounded_line(std::istream& in, std::string& line) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  if (buffer == nullptr) return LineRead::kEnd;
  bool any = false;
  while (true) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      if (!any) return LineRead::kEnd;
      break;
    }
    any = true;
    if (c == '\n') break;
    if (line.size() <= kMaxLineBytes) line.push_back(static_cast<char>(c));
  }
  return line.size() > kMaxLineBytes ? LineRead::kTooLong : LineRead::kLine;
}

// A header behind a '#' (EuRoC/ASL) rather than a comment: as many fields as the mapping needs
// (time and six axes) and not all of them numbers.
bool is_commented_header(std::string_view trimmed, const CsvImportOptions& options) {
  if (trimmed.empty() || trimmed.front() != '#') return false;
  const auto fields = split(trimmed.substr(1), options.delimiter);
  if (fields.size() < 7) return false;
  return std::any_of(fields.begin(), fields.end(), [&](std::string_view field) {
    return !parse_number(field, options.decimal_comma).problem.empty();
  });
}

// Parses the rows after the header; one object per file.
class RowParser {
 public:
  RowParser(const CsvImportOptions& options, const std::string& source, CsvImportSummary& summary)
      : options_(options), source_(source), summary_(summary) {}

  void header(std::string_view line) {
    const auto fields = split(line, options_.delimiter);
    bool all_numbers = true;
    for (const auto& field : fields)
      all_numbers = all_numbers && parse_number(field, options_.decimal_comma).problem.empty();
    if (all_numbers) {
      throw ConfigError(source_, "header",
                        "line " + std::to_string(summary_.lines) +
                            " is numbers, not a header line; read the file without a header (--no-header, "
                            "header: false) or add one");
    }
    for (const auto& field : fields) summary_.header.emplace_back(field);
    if (options_.infer_from_file) {
      HeaderInference inference = infer_from_header(summary_.header, options_, source_);
      options_ = std::move(inference.options);
      summary_.recognised = std::move(inference.description);
    }
    columns_ = resolve_columns(source_, options_, summary_.header);
    expect_fields(summary_.header.size(), "the header");
  }

  void reject_too_long() {
    reject("longer than " + std::to_string(kMaxLineBytes) + " bytes (not read; a broken line end, or not a CSV)");
  }

  void row(std::string_view line, const std::function<void(const ImuCsvSample&)>& on_sample) {
    const auto fields = split(line, options_.delimiter);
    if (!columns_) {  // no header: the first data row sets the field count
      columns_ = resolve_columns(source_, options_, summary_.header);
      expect_fields(fields.size(), "line " + std::to_string(summary_.lines));
    }
    if (fields.size() != expected_fields_) {
      std::string reason = std::to_string(fields.size()) + (fields.size() == 1 ? " field" : " fields") + ", expected " +
                           std::to_string(expected_fields_) + " as in " + expected_from_;
      if (fields.size() == 1 && options_.delimiter != ';' && line.find(';') != std::string_view::npos) {
        reason += " (is the delimiter ';'?)";
      } else if (fields.size() == 1 && options_.delimiter != '\t' && line.find('\t') != std::string_view::npos) {
        reason += " (is the delimiter a tab?)";
      }
      return reject(reason);
    }
    ImuCsvSample sample;
    std::string time_text(fields[columns_->time]);
    if (options_.decimal_comma) std::replace(time_text.begin(), time_text.end(), ',', '.');
    const auto stamp = parse_decimal_time_ns(time_text, options_.time_unit);
    if (!stamp)
      return reject(column_label(summary_.header, columns_->time) + ": '" + std::string(fields[columns_->time]) +
                    "' is not a time");
    if (!add_offset(*stamp, sample.stamp_ns)) return;
    for (int i = 0; i < 3; ++i) {
      if (!read_value(fields, columns_->gyro[i], to_rad_s(options_.gyro_unit), sample.angular_rate_rad_s[i])) return;
    }
    for (int i = 0; i < 3; ++i) {
      if (!read_value(fields, columns_->accel[i], to_m_s2(options_.accel_unit), sample.specific_force_m_s2[i])) return;
    }
    if (columns_->temperature) {
      const std::string_view cell = fields[*columns_->temperature];
      if (is_missing_reading(cell)) {
        ++summary_.rows_without_temperature;
      } else {
        double temperature_c = 0.0;
        if (!read_value(fields, *columns_->temperature, 1.0, temperature_c)) return;
        sample.temperature_c = temperature_c;
      }
    }
    if (summary_.accepted_rows > 0 && sample.stamp_ns <= summary_.last_stamp_ns) {
      // In the file's own times (without the offset), which the user can find in it.
      return reject("time " + format_stamp_s(sample.stamp_ns - *offset_ns_) +
                    " s is not after the previous good row's " + format_stamp_s(summary_.last_stamp_ns - *offset_ns_) +
                    " s");
    }
    if (summary_.accepted_rows == 0) summary_.first_stamp_ns = sample.stamp_ns;
    summary_.last_stamp_ns = sample.stamp_ns;
    ++summary_.accepted_rows;
    on_sample(sample);
  }

 private:
  void expect_fields(std::size_t count, const std::string& where) {
    expected_fields_ = count;
    expected_from_ = where;
    const char* time_units[] = {"s", "ms", "us", "ns"};
    summary_.units = std::string("time ") + time_units[static_cast<int>(options_.time_unit)] + ", gyro " +
                     unit_name(options_.gyro_unit) + ", accel " + unit_name(options_.accel_unit);
    summary_.temperature_column = options_.temperature_column;
    if (columns_->highest >= count) {
      throw ConfigError(source_, "columns",
                        "column " + std::to_string(columns_->highest + 1) + " is mapped, but " + where + " has " +
                            std::to_string(count) + " field" + (count == 1 ? "" : "s") +
                            " (check the delimiter and the column mapping)");
    }
  }

  // The offset is decided at the first time read: a relative time column (see infer_from_file)
  // is moved as a whole, an absolute one left as it is.
  bool add_offset(std::int64_t stamp_ns, std::int64_t& out_ns) {
    if (!offset_ns_) {
      offset_ns_ = options_.time_offset_ns;
      if (options_.infer_from_file && !options_.given.time_offset &&
          static_cast<double>(stamp_ns) < kRelativeTimeLimit_s * 1e9) {
        offset_ns_ = summary_.relative_time_offset_ns = options_.relative_time_offset_ns;
      }
    }
    if (__builtin_add_overflow(stamp_ns, *offset_ns_, &out_ns) || out_ns <= 0 || out_ns > kMaxRosStamp_ns) {
      reject("time " + format_stamp_s(stamp_ns) + " s" +
             (*offset_ns_ != 0 ? " plus the offset " + format_stamp_s(*offset_ns_) + " s" : "") +
             " is outside ROS time (0, 4294967295.999999999] s; a time offset moves it in");
      return false;
    }
    return true;
  }

  bool read_value(const std::vector<std::string_view>& fields, std::size_t column, double scale, double& out) {
    const Number number = parse_number(fields[column], options_.decimal_comma);
    if (!number.problem.empty()) {
      reject(column_label(summary_.header, column) + ": " + number.problem);
      return false;
    }
    out = number.value * scale;
    return true;
  }

  void reject(const std::string& reason) {
    ++summary_.rejected_row_count;
    if (summary_.rejected.size() < options_.max_reported_rows) summary_.rejected.push_back({summary_.lines, reason});
  }

  CsvImportOptions options_;  // a copy: the header may fill in what the options leave open
  const std::string& source_;
  CsvImportSummary& summary_;
  std::optional<ColumnIndices> columns_;
  std::optional<std::int64_t> offset_ns_;
  std::size_t expected_fields_ = 0;
  std::string expected_from_;
};

}  // namespace

AngularRateUnit parse_angular_rate_unit(const std::string& name, const std::string& source, const std::string& key) {
  return parse_name<AngularRateUnit>(
      name, source, key, "angular-rate unit",
      {{"rad_s", AngularRateUnit::kRadPerSecond}, {"deg_s", AngularRateUnit::kDegreePerSecond}});
}

SpecificForceUnit parse_specific_force_unit(const std::string& name, const std::string& source,
                                            const std::string& key) {
  return parse_name<SpecificForceUnit>(
      name, source, key, "specific-force unit",
      {{"m_s2", SpecificForceUnit::kMeterPerSecondSquared}, {"g", SpecificForceUnit::kStandardGravity}});
}

TimeUnit parse_time_unit(const std::string& name, const std::string& source, const std::string& key) {
  return parse_name<TimeUnit>(name, source, key, "time unit",
                              {{"s", TimeUnit::kSecond},
                               {"ms", TimeUnit::kMillisecond},
                               {"us", TimeUnit::kMicrosecond},
                               {"ns", TimeUnit::kNanosecond}});
}

BadRowPolicy parse_bad_row_policy(const std::string& name, const std::string& source, const std::string& key) {
  return parse_name<BadRowPolicy>(name, source, key, "policy",
                                  {{"refuse", BadRowPolicy::kRefuse}, {"skip", BadRowPolicy::kSkip}});
}

char parse_delimiter(const std::string& name, const std::string& source, const std::string& key) {
  if (name == "," || name == "comma") return ',';
  if (name == ";" || name == "semicolon") return ';';
  if (name == "tab" || name == "\t" || name == "\\t") return '\t';
  throw ConfigError(source, key, "unknown delimiter '" + name + "' (',', ';' or tab)");
}

std::int64_t parse_time_offset_ns(const std::string& text, const std::string& source, const std::string& key) {
  const auto offset_ns = parse_decimal_time_ns(text, TimeUnit::kSecond);
  if (!offset_ns) {
    throw ConfigError(source, key, "'" + text + "' is not a number of seconds within +-9.2e9 s (stamps are int64 ns)");
  }
  return *offset_ns;
}

std::string unit_name(AngularRateUnit unit) { return unit == AngularRateUnit::kDegreePerSecond ? "deg_s" : "rad_s"; }
std::string unit_name(SpecificForceUnit unit) { return unit == SpecificForceUnit::kStandardGravity ? "g" : "m_s2"; }

double to_rad_s(AngularRateUnit unit) {
  return unit == AngularRateUnit::kDegreePerSecond ? identify::units::kDegree_rad : 1.0;
}

double to_m_s2(SpecificForceUnit unit) {
  return unit == SpecificForceUnit::kStandardGravity ? identify::units::kStandardGravity_m_s2 : 1.0;
}

std::optional<std::int64_t> parse_decimal_time_ns(const std::string& text, TimeUnit unit) {
  std::string_view rest = trim(text);
  bool negative = false;
  if (!rest.empty() && (rest.front() == '-' || rest.front() == '+')) {
    negative = rest.front() == '-';
    rest.remove_prefix(1);
  }
  std::string digits;
  int fraction_digits = 0;
  bool seen_point = false;
  while (!rest.empty() &&
         (std::isdigit(static_cast<unsigned char>(rest.front())) || (rest.front() == '.' && !seen_point))) {
    if (rest.front() == '.') {
      seen_point = true;
    } else {
      digits += rest.front();
      fraction_digits += seen_point ? 1 : 0;
    }
    rest.remove_prefix(1);
  }
  if (digits.empty()) return std::nullopt;
  long exponent = 0;
  if (!rest.empty() && (rest.front() == 'e' || rest.front() == 'E')) {
    rest.remove_prefix(1);
    const char* begin = rest.data() + (!rest.empty() && rest.front() == '+' ? 1 : 0);
    const auto [end, error] = std::from_chars(begin, rest.data() + rest.size(), exponent);
    if (error != std::errc() || end != rest.data() + rest.size() || std::labs(exponent) > 1000) return std::nullopt;
    rest = {};
  }
  if (!rest.empty()) return std::nullopt;
  // value_ns = digits * 10^shift
  const long shift = exponent - fraction_digits + unit_exponent_to_ns(unit);
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
  if (digits.empty()) return 0;
  bool round_up = false;
  if (shift >= 0) {
    if (static_cast<long>(digits.size()) + shift > 20) return std::nullopt;
    digits.append(static_cast<std::size_t>(shift), '0');
  } else {
    const std::size_t dropped = static_cast<std::size_t>(-shift);
    if (dropped > digits.size()) return 0;  // below half a nanosecond
    round_up = digits[digits.size() - dropped] >= '5';
    digits.resize(digits.size() - dropped);
  }
  std::uint64_t magnitude = 0;
  for (const char digit : digits) {
    if (__builtin_mul_overflow(magnitude, 10u, &magnitude) ||
        __builtin_add_overflow(magnitude, static_cast<unsigned>(digit - '0'), &magnitude)) {
      return std::nullopt;
    }
  }
  magnitude += round_up ? 1 : 0;
  if (magnitude > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) return std::nullopt;
  const auto value = static_cast<std::int64_t>(magnitude);
  return negative ? -value : value;
}

std::string CsvImportSummary::describe_rejections(const std::string& source) const {
  std::ostringstream text;
  text << source << ": " << rejected_row_count << " bad row" << (rejected_row_count == 1 ? "" : "s") << " of "
       << rejected_row_count + accepted_rows << " data rows";
  for (const auto& row : rejected) text << "\n  line " << row.line << ": " << row.reason;
  if (rejected_row_count > rejected.size()) text << "\n  ... and " << rejected_row_count - rejected.size() << " more";
  return text.str();
}

CsvImportSummary parse_imu_csv(std::istream& in, const CsvImportOptions& options, const std::string& source,
                               const std::function<void(const ImuCsvSample&)>& on_sample) {
  check_options(options, source);
  CsvImportSummary summary;
  RowParser parser(options, source, summary);
  bool header_pending = options.has_header;
  std::string line;
  while (true) {
    const LineRead read = read_bounded_line(in, line);
    if (read == LineRead::kEnd) break;
    ++summary.lines;
    if (read == LineRead::kTooLong) {
      if (header_pending) {
        throw InputError(source + ": line " + std::to_string(summary.lines) + " is longer than " +
                         std::to_string(kMaxLineBytes) + " bytes where the header should be: not a CSV of IMU samples");
      }
      parser.reject_too_long();
      continue;
    }
    std::string_view content = line;
    if (summary.lines == 1 && content.substr(0, 3) == "\xEF\xBB\xBF") content.remove_prefix(3);  // UTF-8 BOM
    std::string_view trimmed = trim(content);
    if (header_pending && options.infer_from_file && is_commented_header(trimmed, options)) {
      content = trimmed.substr(1);  // EuRoC/ASL: "#timestamp [ns],w_RS_S_x [rad s^-1],..."
      trimmed = trim(content);
    }
    if (trimmed.empty() || trimmed.front() == '#') continue;
    if (header_pending) {
      parser.header(content);
      header_pending = false;
    } else {
      parser.row(content, on_sample);
    }
  }
  if (in.bad()) throw InputError(source + ": read error after line " + std::to_string(summary.lines));
  if (summary.accepted_rows == 0 && summary.rejected_row_count == 0) {
    throw InputError(source + ": no data rows" + (summary.lines == 0 ? " (the file is empty)" : ""));
  }
  return summary;
}

CsvImportResult parse_imu_csv_text(const std::string& text, const CsvImportOptions& options,
                                   const std::string& source) {
  std::istringstream in(text);
  CsvImportResult result;
  result.summary =
      parse_imu_csv(in, options, source, [&](const ImuCsvSample& sample) { result.samples.push_back(sample); });
  return result;
}

}  // namespace io
}  // namespace imu_lab
