// Rows of the bad-input table: configuration, command line, other input
// files and outputs. The rawlog rows are in bad_input_rawlog_cases.cpp.
#include "bad_input_cases.h"

#include <sys/stat.h>

#include <fstream>

#include "bad_input_support.h"
#include "pmap/common/ply.h"

namespace pmap::testing {
namespace fs = std::filesystem;

namespace {

// A fixture run with default.ini edited: `from` replaced by `to`.
BadInputCase iniCase(const std::string& name, const std::string& from, const std::string& to,
                     int exit_code, const std::string& message) {
  return {name,
          [from, to](const fs::path& d) {
            return mapArgs(writeFixture(d), d, {"--config", editedConfig(d, from, to).string()});
          },
          exit_code, message};
}

std::vector<BadInputCase> iniCases() {
  return {
      {"missing_ini",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d), d, {"--config", (d / "none.ini").string()});
       },
       1, "none.ini"},
      iniCase("missing_include", "@include icp.ini", "@include icp-none.ini", 1, "icp-none.ini"),
      iniCase("missing_section", "@include icp.ini", "", 1, "[ICP]"),
      iniCase("unknown_section", "[Output]", "[Outptu]", 1, "did you mean [Output]?"),
      iniCase("unknown_key", "raw_map = true", "rawmap = true", 1, "did you mean 'raw_map'?"),
      iniCase("unparsable_value", "kappa = 200", "kappa = abc", 1, "kappa"),
      iniCase("value_with_unit", "sigma_m = 0.02", "sigma_m = 2cm", 1, "sigma_m"),
      iniCase("nan_value", "sigma_m = 0.02", "sigma_m = nan", 1, "sigma_m"),
      iniCase("sigma_neither_number_nor_auto", "sigma_m = 0.02", "sigma_m = automatic", 1,
              "not a number or auto"),
      iniCase("inf_value", "z_max_m = 30.0", "z_max_m = inf", 1, "z_max_m"),
      iniCase("negative_size", "sigma_m = 0.02", "sigma_m = -0.02", 1, "sigma_m"),
      iniCase("integer_overflow", "min_support = 60", "min_support = 99999999999", 1,
              "min_support"),
      iniCase("probability_above_one", "seed = 1", "seed = 1\nseed_outlier_probability = 1.5", 1,
              "seed_outlier_probability"),
      iniCase("bad_bool", "raw_map = true", "raw_map = maybe", 1, "raw_map"),
      iniCase("zero_odometry_noise", "loop_closure = true",
              "loop_closure = true\nodometry_noise_fraction = 0", 1, "odometry noise"),
      iniCase("too_many_path_constraints", "loop_closure = true",
              "loop_closure = true\npath_constraints = 50", 1, "path_constraints"),
      iniCase("negative_front_map_radius", "loop_closure = true",
              "loop_closure = true\nfront_map_radius_m = -1", 1, "front_map_radius_m"),
      iniCase("duplicate_key", "kappa = 200", "kappa = 200\nkappa = 300", 1, "duplicate"),
      iniCase("malformed_line", "kappa = 200", "kappa 200", 1, "my.ini:"),
      iniCase("misspelled_mrpt_key", "maxIterations", "maxIteratoins", 1, "maxIterations"),
      {"bom_crlf_and_trailing_spaces_are_fine",
       [](const fs::path& d) {
         const fs::path ini = editedConfig(d, "", "");
         std::ifstream in(ini);
         std::string text = "\xEF\xBB\xBF", line;
         while (std::getline(in, line)) {
           text += line + "   \r\n";
         }
         in.close();
         std::ofstream(ini, std::ios::binary) << text;
         return mapArgs(writeFixture(d), d, {"--config", ini.string()});
       },
       0, ""},
      {"unknown_option",
       [](const fs::path& d) { return mapArgs(writeFixture(d), d, {"--no-such-option"}); }, 1,
       "no-such-option"},
  };
}

std::vector<BadInputCase> otherInputCases() {
  return {
      {"bad_poses_file",
       [](const fs::path& d) {
         std::ofstream(d / "p.txt") << "1767225600 1 2 abc 0 0 0\n";
         return mapArgs(writeFixture(d), d, {"--poses", (d / "p.txt").string()});
       },
       2, "p.txt:1:"},
      {"ply_not_a_ply",
       [](const fs::path& d) {
         std::ofstream(d / "c.ply") << "not a ply\n";
         return std::vector<std::string>{"--cloud", (d / "c.ply").string(), "--out",
                                         (d / "out").string(), "-q"};
       },
       2, "c.ply"},
      {"ply_without_finite_points",
       [](const fs::path& d) {
         std::ofstream(d / "c.ply") << "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                       "property float y\nproperty float z\nend_header\n"
                                       "nan 0 0\n0 nan 0\n";
         return std::vector<std::string>{"--cloud", (d / "c.ply").string(), "--out",
                                         (d / "out").string(), "-q"};
       },
       2, "no finite points"},
  };
}

std::vector<BadInputCase> outputCasesList() {
  return {
      {"out_is_the_input_rawlog",
       [](const fs::path& d) {
         const fs::path p = writeFixture(d);
         return std::vector<std::string>{"--rawlog", p.string(), "--out", p.string(), "-q"};
       },
       4, "the output directory is the input file"},
      {"out_would_overwrite_the_poses",
       [](const fs::path& d) {
         const fs::path p = writeFixture(d);
         fs::create_directories(d / "out");
         std::ofstream(d / "out" / "poses.txt") << "# given poses\n";
         return mapArgs(p, d, {"--poses", (d / "out" / "poses.txt").string()});
       },
       4, "would overwrite the input file"},
      {"out_would_overwrite_the_cloud",
       [](const fs::path& d) {
         fs::create_directories(d / "out");
         std::ofstream(d / "out" / "points.ply")
             << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                "property float y\nproperty float z\nend_header\n0 0 0\n";
         return std::vector<std::string>{"--cloud", (d / "out" / "points.ply").string(), "--out",
                                         (d / "out").string(), "-q"};
       },
       4, "would overwrite the input file"},
      {"out_under_a_regular_file",
       [](const fs::path& d) {
         std::ofstream(d / "file.txt") << "x";
         return std::vector<std::string>{"--rawlog", writeFixture(d).string(), "--out",
                                         (d / "file.txt" / "out").string(), "-q"};
       },
       4, "cannot create output directory"},
      {"out_read_only_directory",
       [](const fs::path& d) {
         fs::create_directories(d / "out");
         ::chmod((d / "out").c_str(), 0555);
         return mapArgs(writeFixture(d), d);
       },
       4,
       "not writable",
       {},
       true},
      {"out_in_proc",
       [](const fs::path& d) {
         return std::vector<std::string>{"--rawlog", writeFixture(d).string(), "--out",
                                         "/proc/pmap-cannot-write", "-q"};
       },
       4, "/proc/pmap-cannot-write"},
  };
}

}  // namespace

std::vector<BadInputCase> configCases() {
  std::vector<BadInputCase> all = iniCases();
  const auto other = otherInputCases();
  all.insert(all.end(), other.begin(), other.end());
  return all;
}

std::vector<BadInputCase> outputCases() {
  return outputCasesList();
}

std::vector<BadInputCase> badInputCases() {
  std::vector<BadInputCase> all = rawlogCases();
  for (auto&& group : {configCases(), outputCases()}) {
    all.insert(all.end(), group.begin(), group.end());
  }
  return all;
}

}  // namespace pmap::testing
