// Rows of the bad-input table: the rawlog and its scans.
#include <sys/stat.h>

#include <fstream>

#include "bad_input_cases.h"
#include "bad_input_support.h"
#include "corruption.h"

namespace pmap::testing {
namespace fs = std::filesystem;
using Args = std::vector<std::string>;

namespace {

FixtureOptions plain() {
  FixtureOptions o;
  o.gzip = false;
  return o;
}

// A plain fixture with its bytes edited by `edit`.
fs::path editedFixture(const fs::path& dir, const std::function<void(Bytes&)>& edit) {
  const fs::path p = writeFixture(dir, plain());
  Bytes b = readFileBytes(p);
  edit(b);
  writeFileBytes(p, b);
  return p;
}

// One uint32 length field (the first one equal to `value` after the first
// `skip` bytes) set to `huge`.
std::function<void(Bytes&)> corruptLength(std::uint32_t value, std::uint32_t huge) {
  return [value, huge](Bytes& b) {
    const auto at = findUint32(b, value);
    ASSERT_FALSE(at.empty());
    putUint32(b, at[at.size() / 2], huge);
  };
}

// Input cases: the file itself.
std::vector<BadInputCase> fileCases() {
  return {
      {"missing_rawlog", [](const fs::path& d) { return mapArgs(d / "none.rawlog", d); }, 2,
       "none.rawlog: rawlog not found"},
      {"rawlog_is_a_directory", [](const fs::path& d) { return mapArgs(d, d); }, 2,
       "is a directory"},
      {"unreadable_rawlog",
       [](const fs::path& d) {
         const fs::path p = writeFixture(d);
         ::chmod(p.c_str(), 0);
         ::chmod(d.c_str(), 0777);  // --out's folder writable: the rawlog is the only problem
         return mapArgs(p, d);
       },
       2,
       "cannot open for reading",
       {},
       true},
      {"empty_rawlog",
       [](const fs::path& d) {
         std::ofstream(d / "e.rawlog").close();
         return mapArgs(d / "e.rawlog", d);
       },
       2, "empty file"},
      {"text_file_not_a_rawlog",
       [](const fs::path& d) {
         std::ofstream(d / "t.rawlog") << "x y z\n1 2 3\n";
         return mapArgs(d / "t.rawlog", d);
       },
       2, "record 0 at byte 0: not a rawlog"},
      {"random_bytes",
       [](const fs::path& d) {
         Bytes b(4096, '\0');
         flipBytes(b, 7, 4096);
         writeFileBytes(d / "r.rawlog", b);
         return mapArgs(d / "r.rawlog", d);
       },
       2, "record 0 at byte 0"},
      {"truncated_plain",
       [](const fs::path& d) {
         truncateCopy(writeFixture(d, plain()), d / "cut.rawlog", 0.51);
         return mapArgs(d / "cut.rawlog", d);
       },
       2, "truncated file"},
      {"truncated_gzip",
       [](const fs::path& d) {
         truncateCopy(writeFixture(d), d / "cut.rawlog", 0.51);
         return mapArgs(d / "cut.rawlog", d);
       },
       2, "truncated file"},
      {"flipped_gzip_bytes",
       [](const fs::path& d) {
         const fs::path p = writeFixture(d);
         Bytes b = readFileBytes(p);
         for (std::size_t i = b.size() / 2; i < b.size() / 2 + 8; ++i) {
           b[i] = static_cast<char>(b[i] ^ 0x5a);
         }
         writeFileBytes(p, b);
         return mapArgs(p, d);
       },
       2, "corrupt"},
  };
}

// Input cases: the serialized objects inside a readable file.
std::vector<BadInputCase> recordCases() {
  return {
      {"corrupt_scan_length",  // 181 beams -> 2^31 - 1
       [](const fs::path& d) {
         return mapArgs(editedFixture(d, corruptLength(181, 0x7fffffff)), d);
       },
       2, "a size field asks for more than"},
      {"corrupt_string_length",  // "LASER_V" (7) -> 4 GiB
       [](const fs::path& d) {
         return mapArgs(editedFixture(d,
                                      [](Bytes& b) {
                                        const auto at = findText(b, "LASER_V");
                                        ASSERT_FALSE(at.empty());
                                        putUint32(b, at[at.size() / 2] - 4, 0xfffffff0u);
                                      }),
                        d);
       },
       2, "a size field asks for more than"},
      {"unknown_class",
       [](const fs::path& d) {
         return mapArgs(editedFixture(d,
                                      [](Bytes& b) {
                                        const auto at = findText(b, "CObservationOdometry");
                                        ASSERT_FALSE(at.empty());
                                        b[at[3] + 19] = 'x';  // ...Odometrx
                                      }),
                        d);
       },
       2, "record 9 at byte"},
      {"no_usable_scans",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d), d, {"--keep-label", "ODOMETRY"});
       },
       2, "no usable scans"},
      {"no_structure_sensor",
       [](const fs::path& d) {
         FixtureOptions o;
         o.vertical = false;
         return mapArgs(writeFixture(d, o), d);
       },
       1, "[Sensors] structure = LASER_V: no usable structure observation"},
      {"unknown_structure_label",
       [](const fs::path& d) {
         FixtureOptions o;
         o.laser_v_label = "LASER_X";
         return mapArgs(writeFixture(d, o), d);
       },
       1, "'LASER_X' (CObservation2DRangeScan) x 20"},
  };
}

FixtureOptions withTimestamps(TimestampFault fault) {
  FixtureOptions o;
  o.timestamps = fault;
  return o;
}

// Timestamps and poses.
std::vector<BadInputCase> timeCases() {
  return {
      {"zero_timestamps",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withTimestamps(TimestampFault::kZero)), d);
       },
       0, "",
       [](const fs::path& d) {
         EXPECT_EQ(expectValidMap(d)["input"]["invalid_timestamps"], 12);  // 4 cycles x 3
       }},
      {"duplicate_timestamps",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withTimestamps(TimestampFault::kDuplicate)), d);
       },
       0, "",
       [](const fs::path& d) {  // a repeated time replaces the pose (not counted)
         EXPECT_EQ(expectValidMap(d)["scans"], 19);
       }},
      {"backwards_timestamps",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withTimestamps(TimestampFault::kBackwards)), d);
       },
       0, "", [](const fs::path& d) { EXPECT_GT(expectValidMap(d)["poses"]["non_monotonic"], 0); }},
      {"nan_odometry",
       [](const fs::path& d) {
         FixtureOptions o;
         o.nan_odometry = true;
         return mapArgs(writeFixture(d, o), d);
       },
       0, "",
       [](const fs::path& d) {  // the reading is not used; ICP carries on
         const auto s = expectValidMap(d);
         EXPECT_EQ(s["input"]["non_finite_poses"], 1);
         EXPECT_EQ(s["scans"], 19);
       }},
      {"nan_odometry_action",
       [](const fs::path& d) {
         FixtureOptions o;
         o.format = FixtureFormat::kSensoryFrames;
         o.nan_odometry = true;
         return mapArgs(writeFixture(d, o), d);
       },
       0, "",
       [](const fs::path& d) { EXPECT_EQ(expectValidMap(d)["input"]["non_finite_poses"], 2); }},
  };
}

FixtureOptions withRanges(StructureRanges ranges) {
  FixtureOptions o;
  o.ranges = ranges;
  return o;
}

// The structure scans' contents.
std::vector<BadInputCase> scanCases() {
  return {
      {"nan_and_inf_ranges_flagged_valid",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withRanges(StructureRanges::kNanValid)), d);
       },
       0, "",
       [](const fs::path& d) {
         const auto s = expectValidMap(d);
         // 26 of 181 beams in each of the 20 scans (the last one has no pose)
         EXPECT_EQ(s["points_dropped_by_reason"]["non_finite"], 20 * 26);
         EXPECT_EQ(s["points"], 19 * (181 - 26));  // scans kept
       }},
      {"zero_and_negative_ranges",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withRanges(StructureRanges::kNegative)), d);
       },
       0, "",
       [](const fs::path& d) {
         EXPECT_EQ(expectValidMap(d)["points_dropped_by_reason"]["out_of_range"], 20 * 37);
       }},
      {"nothing_found_all_ranges_invalid",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withRanges(StructureRanges::kAllInvalid)), d);
       },
       0, "planar-mapper: warning: nothing found",
       [](const fs::path& d) {
         const auto s = expectValidMap(d);
         EXPECT_EQ(s["points"], 0);
         EXPECT_EQ(s["surfaces"], 0);
         EXPECT_TRUE(fs::exists(d / "out" / "map.glb"));
         EXPECT_FALSE(s["warnings"].empty());
       }},
      {"nothing_planar_scattered_ranges",
       [](const fs::path& d) {
         return mapArgs(writeFixture(d, withRanges(StructureRanges::kScattered)), d);
       },
       0, "planar-mapper: warning: nothing found",
       [](const fs::path& d) {
         const auto s = expectValidMap(d);
         EXPECT_EQ(s["surfaces"], 0);
         EXPECT_GT(s["points"], 0);
       }},
      {"far_from_the_origin",
       [](const fs::path& d) {
         FixtureOptions o;
         o.offset_x_m = 1e6;
         return mapArgs(writeFixture(d, o), d, {"--mode", "offline"});
       },
       0, "",
       [](const fs::path& d) {
         const auto s = expectValidMap(d);
         EXPECT_GE(s["surfaces"], 3);  // both walls and the ceiling, as at the origin
       }},
  };
}

}  // namespace

std::vector<BadInputCase> rawlogCases() {
  std::vector<BadInputCase> all;
  for (auto&& group : {fileCases(), recordCases(), timeCases(), scanCases()}) {
    all.insert(all.end(), group.begin(), group.end());
  }
  return all;
}

}  // namespace pmap::testing
