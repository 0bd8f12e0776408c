#include "cli/study_runs.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>

namespace fp {
namespace {

/// `text` as a file-name part: letters, digits and . _ + - = kept, the rest '_'; long texts
/// cut, with a hash of the whole so that different values stay apart.
std::string file_name_part(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '+' || c == '-' || c == '=';
    out += keep ? c : '_';
  }
  if (out.size() > 40) {
    std::ostringstream h;
    h << std::hex << (std::hash<std::string>{}(text) & 0xffffffu);
    out = out.substr(0, 32) + "~" + h.str();
  }
  return out;
}

}  // namespace

std::vector<StudyRun> study_runs(const StudySpec& spec) {
  std::vector<StudyRun> runs;
  std::vector<std::size_t> levels(spec.parameters.size(), 0);
  std::map<std::string, int> used;
  while (true) {
    for (const std::uint64_t seed : spec.seeds) {
      StudyRun run;
      run.levels = levels;
      run.seed = seed;
      run.scene_path = spec.scene_path;
      for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
        const StudyParameter& par = spec.parameters[p];
        const StudyLevel& level = par.levels[levels[p]];
        run.name += file_name_part(par.name_part) + "=" + file_name_part(level.name_part) + ",";
        run.overrides.insert(run.overrides.end(), level.overrides.begin(), level.overrides.end());
        if (!level.scene_path.empty()) run.scene_path = level.scene_path;
      }
      run.name += "seed=" + std::to_string(seed);
      if (const int n = used[run.name]++; n > 0) run.name += "~" + std::to_string(n);
      runs.push_back(std::move(run));
    }
    // The next combination: the last parameter varies fastest.
    std::size_t p = spec.parameters.size();
    while (p > 0 && ++levels[p - 1] == spec.parameters[p - 1].levels.size()) levels[--p] = 0;
    if (p == 0) break;
  }
  return runs;
}

StudyRunFiles study_run_files(const StudySpec& spec, const StudyRun& run) {
  const std::filesystem::path folder = std::filesystem::path(spec.output_dir) / "runs" / run.name;
  return {folder.string(), (folder / "record.json").string(), (folder / (run.shapes ? "packing.json" : "packing.csv")).string(),
          (folder / "log.txt").string()};
}

std::optional<std::string> study_run_record(const StudySpec& spec, const StudyRun& run, const std::string& base_scene_text) {
  const StudyRunFiles files = study_run_files(spec, run);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(files.record, ec)) return std::nullopt;
  if (spec.keep_packings && !std::filesystem::is_regular_file(files.packing, ec)) return std::nullopt;
  std::ifstream in(files.record, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json record = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!record.is_object() || !record.contains("scene") || !record.contains("seed")) return std::nullopt;
  const nlohmann::json& scene = record["scene"];
  std::vector<std::string> changes;
  for (const auto& o : run.overrides) changes.push_back(o.key + "=" + o.value);
  const nlohmann::json recorded = scene.value("overrides", nlohmann::json::array());
  const bool this_run = scene.value("path", std::string()) == run.scene_path && scene.value("text", std::string()) == base_scene_text &&
                        recorded == nlohmann::json(changes) && record["seed"] == nlohmann::json(run.seed);
  if (!this_run) return std::nullopt;
  return text;
}

}  // namespace fp
