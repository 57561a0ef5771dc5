#include "pmap/mapper/mapper_config.h"

#include <algorithm>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/config/section_reader.h"

namespace pmap::mapper {
namespace {

const std::vector<std::string>& projectSections() {
  static const std::vector<std::string> s = {"Sensors", "Output"};
  return s;
}

bool ownedByMrpt(const std::string& section) {
  for (const auto& m : mrptSections()) {
    if (m.back() == '*' ? section.rfind(m.substr(0, m.size() - 1), 0) == 0 : section == m) {
      return true;
    }
  }
  return false;
}

void rejectUnknownSections(const config::IniDocument& doc) {
  std::vector<std::string> known = projectSections();
  known.push_back("ICP");
  known.push_back("MappingApplication");
  for (const auto& s : doc.sectionNames()) {
    const bool project =
        std::find(projectSections().begin(), projectSections().end(), s) != projectSections().end();
    if (!project && !ownedByMrpt(s)) {
      const std::string near = nearestWord(s, known);
      throw ConfigError(doc.origin() + ": unknown section [" + s + "]" +
                        (near.empty() ? "" : " (did you mean [" + near + "]?)"));
    }
  }
}

}  // namespace

const std::vector<std::string>& mrptSections() {
  static const std::vector<std::string> s = {"ICP", "MappingApplication*"};
  return s;
}

void OutputOptions::load(config::SectionReader& reader) {
  reader.read("raw_map", raw_map);
  reader.read("raw_max_edge_m", raw_mesh.max_edge_m);
}

bool OutputOptions::validate(std::string* why) const {
  return raw_mesh.validate(why);
}

MapperConfig loadMapperConfig(const std::filesystem::path& path) {
  MapperConfig cfg{
      config::IniDocument::load(path), std::make_shared<config::EffectiveConfig>(), {}, {}};
  rejectUnknownSections(cfg.doc);
  config::loadOptions(cfg.doc, "Sensors", cfg.sensors, cfg.effective.get());
  config::loadOptions(cfg.doc, "Output", cfg.output, cfg.effective.get());
  return cfg;
}

}  // namespace pmap::mapper
