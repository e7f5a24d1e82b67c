#include "imu_lab/io/stability_table.h"

#include <map>
#include <sstream>
#include <stdexcept>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/format_number.h"

namespace imu_lab {
namespace io {
namespace {

const char* const kFields[] = {"dev", "lo", "hi", "edf", "n", "alpha"};

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream stream(line);
  while (std::getline(stream, cell, separator)) cells.push_back(cell);
  if (!line.empty() && line.back() == separator) cells.emplace_back();
  return cells;
}

}  // namespace

std::string format_stability_csv(const std::vector<ChannelCurve>& channels) {
  // Keyed by the averaging factor: taus of different channels compare exactly through it.
  std::map<int, double> tau_by_factor;
  std::vector<std::map<int, const allan::StabilityPoint*>> by_factor(channels.size());
  for (std::size_t c = 0; c < channels.size(); ++c) {
    for (const auto& point : channels[c].points) {
      tau_by_factor[point.averaging_factor] = point.tau_s;
      by_factor[c][point.averaging_factor] = &point;
    }
  }
  std::ostringstream out;
  out << "tau_s,m";
  for (const auto& channel : channels) {
    out << ',' << channel.name << "_dev_" << channel.unit << ',' << channel.name << "_lo_" << channel.unit << ','
        << channel.name << "_hi_" << channel.unit << ',' << channel.name << "_edf," << channel.name << "_n,"
        << channel.name << "_alpha";
  }
  out << '\n';
  for (const auto& row : tau_by_factor) {
    out << format_number(row.second) << ',' << row.first;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const auto found = by_factor[c].find(row.first);
      if (found == by_factor[c].end()) {
        out << ",,,,,,";
        continue;
      }
      const allan::StabilityPoint& p = *found->second;
      out << ',' << format_number(p.deviation) << ',' << format_number(p.deviation_lower) << ','
          << format_number(p.deviation_upper) << ',' << format_number(p.edf) << ',' << p.term_count << ',' << p.alpha;
    }
    out << '\n';
  }
  return out.str();
}

void write_stability_csv(const std::string& path, const std::vector<ChannelCurve>& channels) {
  write_file_atomically(path, format_stability_csv(channels));
}

std::vector<ChannelCurve> parse_stability_csv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) throw std::invalid_argument("stability CSV: empty");
  const std::vector<std::string> header = split(line, ',');
  const std::size_t field_count = sizeof(kFields) / sizeof(kFields[0]);
  if (header.size() < 2 || header[0] != "tau_s" || (header.size() - 2) % field_count != 0) {
    throw std::invalid_argument("stability CSV: unexpected header: " + line);
  }
  std::vector<ChannelCurve> channels((header.size() - 2) / field_count);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const std::string& deviation_column = header[2 + c * field_count];
    const auto marker = deviation_column.find("_dev_");
    if (marker == std::string::npos) throw std::invalid_argument("stability CSV: bad column " + deviation_column);
    channels[c].name = deviation_column.substr(0, marker);
    channels[c].unit = deviation_column.substr(marker + 5);
  }
  std::size_t line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    const std::vector<std::string> cells = split(line, ',');
    if (cells.size() != header.size()) {
      throw std::invalid_argument("stability CSV line " + std::to_string(line_number) + ": " +
                                  std::to_string(cells.size()) + " cells, expected " + std::to_string(header.size()));
    }
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::size_t first = 2 + c * field_count;
      if (cells[first].empty()) continue;
      allan::StabilityPoint p;
      p.tau_s = std::stod(cells[0]);
      p.averaging_factor = std::stoi(cells[1]);
      p.deviation = std::stod(cells[first]);
      p.deviation_lower = std::stod(cells[first + 1]);
      p.deviation_upper = std::stod(cells[first + 2]);
      p.edf = std::stod(cells[first + 3]);
      p.term_count = std::stoll(cells[first + 4]);
      p.alpha = std::stoi(cells[first + 5]);
      channels[c].points.push_back(p);
    }
  }
  return channels;
}

}  // namespace io
}  // namespace imu_lab
