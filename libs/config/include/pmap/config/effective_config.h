// The configuration a run actually used: every key read, with the value in
// force (from the file or the default). Written beside the outputs as an ini
// that reproduces the run.
#pragma once

#include <string>
#include <vector>

namespace pmap::config {

class EffectiveConfig {
 public:
  /// Records section/key = value (later records of the same key replace the
  /// value in place). `from_default` marks values the file did not set.
  void record(const std::string& section, const std::string& key, const std::string& value,
              bool from_default);

  /// The ini text: sections in first-recorded order, keys in recorded order;
  /// defaulted keys carry a "; default" comment. `header` lines are written
  /// first as comments.
  std::string toIniText(const std::vector<std::string>& header = {}) const;

  struct Entry {
    std::string key;
    std::string value;
    bool from_default = false;
  };
  struct Section {
    std::string name;
    std::vector<Entry> entries;
  };
  const std::vector<Section>& sections() const { return sections_; }

 private:
  std::vector<Section> sections_;
};

}  // namespace pmap::config
