#include "cli/study_table.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "cli/pack_check.hpp"

namespace fp {
namespace {

using Json = nlohmann::ordered_json;

void add(StudyRow& row, const std::string& key, const std::string& value) {
  if (row.values.emplace(key, value).second) row.keys.push_back(key);
}

void flatten(const Json& j, const std::string& prefix, StudyRow& row) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (prefix.empty() && it.key() == "scene") continue;  // the run's identity says it
      flatten(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), row);
    }
  } else if (j.is_string()) {
    add(row, prefix, j.get<std::string>());
  } else if (j.is_boolean() || j.is_number()) {
    add(row, prefix, j.dump());  // numbers as nlohmann writes them: the shortest text that reads back exactly
  }
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// The CSV of `rows` with these columns (a run not ended yet, without keys, is left out).
std::string csv_of(const std::vector<StudyRow>& rows, const std::vector<std::string>& columns) {
  std::string out;
  for (std::size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + csv_field(columns[c]);
  out += '\n';
  for (const auto& row : rows) {
    if (row.keys.empty()) continue;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const auto it = row.values.find(columns[c]);
      out += (c ? "," : "") + csv_field(it == row.values.end() ? std::string() : it->second);
    }
    out += '\n';
  }
  return out;
}

}  // namespace

StudyRow study_row(const StudySpec& spec, const StudyRun& run, const std::string& record_text, const std::string& failure) {
  StudyRow row;
  add(row, "run", run.name);
  for (std::size_t p = 0; p < spec.parameters.size(); ++p)
    add(row, spec.parameters[p].name, spec.parameters[p].levels[run.levels[p]].label);
  add(row, "seed", std::to_string(run.seed));
  if (record_text.empty()) {
    add(row, "status", "failed");
    add(row, "message", failure);
    return row;
  }
  const Json record = Json::parse(record_text);
  const Json info = record.value("info", Json::object());
  const std::string verdict = info.value("validation", std::string());
  const bool valid = verdict == "ok" || verdict == kShortOfRoomVerdict;
  add(row, "status", !valid ? "invalid" : info.contains("incomplete") ? "incomplete" : "ok");
  add(row, "message", valid ? info.value("incomplete", std::string()) : "");
  flatten(record, "", row);
  return row;
}

std::string study_csv(const std::vector<StudyRow>& rows) {
  std::vector<std::string> columns;
  std::set<std::string> seen;
  for (const auto& row : rows)
    for (const auto& k : row.keys)
      if (seen.insert(k).second) columns.push_back(k);
  return csv_of(rows, columns);
}

std::string study_short_csv(const StudySpec& spec, const std::vector<StudyRow>& rows) {
  std::vector<std::string> columns{"run"};
  for (const auto& p : spec.parameters) columns.push_back(p.name);
  columns.insert(columns.end(), {"seed", "status"});
  for (const char* figure : kStudyMainFigures)
    if (std::any_of(rows.begin(), rows.end(), [&](const StudyRow& r) { return r.values.count(figure) > 0; })) columns.push_back(figure);
  columns.push_back("message");
  // Figures to read at a glance: 5 significant digits (results-full.csv keeps every digit).
  std::vector<StudyRow> shown = rows;
  for (StudyRow& row : shown)
    for (const char* figure : kStudyMainFigures)
      if (auto it = row.values.find(figure); it != row.values.end() && it->second.find_first_of(".eE") != std::string::npos) {
        char* end = nullptr;
        const double v = std::strtod(it->second.c_str(), &end);
        if (end != it->second.c_str() && *end == '\0') {
          char buf[32];
          std::snprintf(buf, sizeof buf, "%.5g", v);
          it->second = buf;
        }
      }
  return csv_of(shown, columns);
}

std::string study_value(const StudyRow& row, const std::string& key) {
  const auto it = row.values.find(key);
  return it == row.values.end() ? std::string() : it->second;
}

}  // namespace fp
