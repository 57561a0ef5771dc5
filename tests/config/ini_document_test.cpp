#include "pmap/config/ini_document.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "pmap/common/error.h"

namespace pmap::config {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(PMAP_SOURCE_DIR) / "tests" / "config" / "data";

/// The ConfigError message of parsing `text` as "cfg.ini" (fails if none).
std::string parseError(const std::string& text, const fs::path& base_dir = ".") {
  try {
    IniDocument::parse(text, "cfg.ini", base_dir);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return {};
}

std::string loadError(const fs::path& path) {
  try {
    IniDocument::load(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError for " << path;
  return {};
}

std::string valueOf(const IniDocument& doc, const std::string& section, const std::string& key) {
  const IniValue* v = doc.find(section, key);
  EXPECT_NE(v, nullptr) << "[" << section << "] " << key;
  return v ? v->value : std::string("<absent>");
}

fs::path tmpDir(const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / ("config_ini_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(IniDocument, ParsesSectionsKeysAndValuesInFileOrder) {
  const auto doc = IniDocument::parse("[B]\nz = 1\na = two words\n[A]\nk=v\n", "cfg.ini");
  EXPECT_EQ(doc.origin(), "cfg.ini");
  EXPECT_EQ(doc.sectionNames(), (std::vector<std::string>{"B", "A"}));
  EXPECT_EQ(doc.keys("B"), (std::vector<std::string>{"z", "a"}));
  EXPECT_EQ(valueOf(doc, "B", "a"), "two words");
  EXPECT_EQ(valueOf(doc, "A", "k"), "v");
  EXPECT_TRUE(doc.keys("C").empty());
  EXPECT_FALSE(doc.hasSection("C"));
  EXPECT_EQ(doc.find("B", "k"), nullptr);
  EXPECT_EQ(doc.location("B", "a"), "cfg.ini:3");
  EXPECT_EQ(doc.location("B", "nope"), "cfg.ini");
}

TEST(IniDocument, EmptyTextIsAnEmptyDocument) {
  const auto doc = IniDocument::parse("", "cfg.ini");
  EXPECT_TRUE(doc.sectionNames().empty());
  EXPECT_TRUE(IniDocument::parse("\n\n ; only comments\n", "cfg.ini").sectionNames().empty());
}

TEST(IniDocument, SectionsAndKeysAreCaseSensitive) {
  const auto doc = IniDocument::parse("[ICP]\nALFA = 1\nalfa = 2\n", "cfg.ini");
  EXPECT_FALSE(doc.hasSection("icp"));
  EXPECT_EQ(valueOf(doc, "ICP", "ALFA"), "1");
  EXPECT_EQ(valueOf(doc, "ICP", "alfa"), "2");
}

TEST(IniDocument, StripsWholeLineAndInlineComments) {
  const auto doc = IniDocument::parse(
      "; c1\n# c2\n// c3\n[S]  // section comment\n"
      "a = 1 ; x\nb = 2 # y\nc = 3 // z\nurl = http://x/y\nsemi = a;b\nhash = a#b\n"
      "tab = 4\t;t\nd = ; only a comment\n",
      "cfg.ini");
  EXPECT_EQ(valueOf(doc, "S", "a"), "1");
  EXPECT_EQ(valueOf(doc, "S", "b"), "2");
  EXPECT_EQ(valueOf(doc, "S", "c"), "3");
  EXPECT_EQ(valueOf(doc, "S", "url"), "http://x/y");
  EXPECT_EQ(valueOf(doc, "S", "semi"), "a;b");
  EXPECT_EQ(valueOf(doc, "S", "hash"), "a#b");
  EXPECT_EQ(valueOf(doc, "S", "tab"), "4");
  EXPECT_EQ(valueOf(doc, "S", "d"), "");
}

TEST(IniDocument, QuotedValuesKeepSpacesAndCommentCharacters) {
  const auto doc = IniDocument::parse(
      "[S]\nsp = \"  padded \"  ; comment\nc = \"a ; b # c // d\"\nempty = \"\"\n"
      "esc = \"say \\\"hi\\\" \\\\ \\${X}\"\nwin = \"C:\\dir\"\ninner = a \"b\" c\n",
      "cfg.ini");
  EXPECT_EQ(valueOf(doc, "S", "sp"), "  padded ");
  EXPECT_EQ(valueOf(doc, "S", "c"), "a ; b # c // d");
  EXPECT_EQ(valueOf(doc, "S", "empty"), "");
  EXPECT_EQ(valueOf(doc, "S", "esc"), "say \"hi\" \\ ${X}");
  EXPECT_EQ(valueOf(doc, "S", "win"), "C:\\dir");
  EXPECT_EQ(valueOf(doc, "S", "inner"), "a \"b\" c");
}

TEST(IniDocument, BadQuotingIsAnError) {
  EXPECT_EQ(parseError("[S]\na = \"open\n"), "cfg.ini:2: unterminated quoted value '\"open'");
  EXPECT_EQ(parseError("[S]\na = \"x\" y\n"),
            "cfg.ini:2: unexpected text 'y' after the closing quote");
}

TEST(IniDocument, EmptyValueIsAllowed) {
  const auto doc = IniDocument::parse("[S]\nlabel =\nother=   \n", "cfg.ini");
  EXPECT_EQ(valueOf(doc, "S", "label"), "");
  EXPECT_EQ(valueOf(doc, "S", "other"), "");
}

TEST(IniDocument, AcceptsBomCrlfTabsAndTrailingSpaces) {
  const auto doc = IniDocument::load(kData / "bom_crlf.ini");
  EXPECT_EQ(doc.sectionNames(), (std::vector<std::string>{"ICP"}));
  EXPECT_EQ(valueOf(doc, "ICP", "maxIterations"), "80");
  EXPECT_EQ(valueOf(doc, "ICP", "ALFA"), "0.8");
  EXPECT_EQ(valueOf(doc, "ICP", "label"), "");
  EXPECT_EQ(doc.location("ICP", "ALFA"), (kData / "bom_crlf.ini").string() + ":3");
}

TEST(IniDocument, MalformedLineNamesFileAndLine) {
  EXPECT_EQ(parseError("[S]\na = 1\nfoo\n"),
            "cfg.ini:3: malformed line 'foo' (expected 'key = value', '[Section]' or a comment)");
  EXPECT_NE(parseError("[S]\n= 1\n").find("cfg.ini:2: malformed line '= 1'"), std::string::npos);
  EXPECT_NE(parseError("[S]\nmy key = 1\n").find("cfg.ini:2: malformed line"), std::string::npos);
}

TEST(IniDocument, MalformedSectionHeaders) {
  EXPECT_EQ(parseError("[S\n"), "cfg.ini:1: malformed line '[S' (expected '[Section]')");
  EXPECT_NE(parseError("[]\n").find("cfg.ini:1: malformed line '[]'"), std::string::npos);
  EXPECT_NE(parseError("[S] x\n").find("cfg.ini:1: malformed line '[S] x'"), std::string::npos);
}

TEST(IniDocument, ErrorMessagesStayOnOneLine) {
  const std::string msg = parseError("[S]\nbad\x01\x7f" + std::string(200, 'x') + "\n");
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  EXPECT_NE(msg.find("bad\\x01\\x7f"), std::string::npos);
  EXPECT_LT(msg.size(), 200u);
}

TEST(IniDocument, KeyOutsideAnySectionIsAnError) {
  EXPECT_EQ(parseError("a = 1\n[S]\n"),
            "cfg.ini:1: key 'a' outside any section (add a '[Section]' line above it)");
}

TEST(IniDocument, DuplicateKeyNamesBothLines) {
  EXPECT_EQ(parseError("[PlanarEM]\nsigma_m = 1\n\nsigma_m = 2\n"),
            "cfg.ini:4: duplicate key 'sigma_m' in [PlanarEM] (first at line 2)");
}

TEST(IniDocument, ReopenedSectionMergesButKeepsKeysUnique) {
  const auto doc = IniDocument::parse("[A]\nx = 1\n[B]\ny = 2\n[A]\nz = 3\n", "cfg.ini");
  EXPECT_EQ(doc.sectionNames(), (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(doc.keys("A"), (std::vector<std::string>{"x", "z"}));
  EXPECT_EQ(parseError("[A]\nx = 1\n[B]\n[A]\nx = 3\n"),
            "cfg.ini:5: duplicate key 'x' in [A] (first at line 2)");
}

TEST(IniDocument, MissingFileOrDirectoryIsAnError) {
  const fs::path missing = kData / "no_such_file.ini";
  EXPECT_EQ(loadError(missing), missing.string() + ": cannot open file");
  EXPECT_EQ(loadError(kData), kData.string() + ": cannot open file (it is a directory)");
}

// A device never ends (/dev/zero) or blocks (a FIFO); a huge file is not an
// ini: both are refused before reading, as file or as @include target.
TEST(IniDocument, DevicesAndHugeFilesAreNotRead) {
  EXPECT_EQ(loadError("/dev/zero"), "/dev/zero: not a regular file (a device, FIFO or socket)");
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "ini_devices";
  fs::create_directories(dir);
  std::ofstream(dir / "inc.ini") << "[A]\n@include /dev/zero\n";
  EXPECT_NE(loadError(dir / "inc.ini").find("/dev/zero"), std::string::npos);
  {
    std::ofstream big(dir / "big.ini");
    big << "[A]\n";
    for (int i = 0; i < 300000; ++i) {
      big << "; a comment line to make the file larger than four MiB\n";
    }
  }
  EXPECT_EQ(loadError(dir / "big.ini"),
            (dir / "big.ini").string() + ": file larger than 4 MiB, not an ini file");
}

TEST(IniDocument, IncludeResolvesRelativeToTheIncludingFile) {
  const auto doc = IniDocument::load(kData / "with_include.ini");
  EXPECT_EQ(doc.sectionNames(), (std::vector<std::string>{"PlanarEM", "Sensors"}));
  EXPECT_EQ(doc.keys("PlanarEM"),
            (std::vector<std::string>{"sigma_m", "min_points", "max_iterations"}));
  EXPECT_EQ(valueOf(doc, "PlanarEM", "sigma_m"), "0.05");
  EXPECT_EQ(valueOf(doc, "Sensors", "label"), "LASER1");
  const IniValue* v = doc.find("PlanarEM", "min_points");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->file, (kData / "included" / "common.ini").string());
  EXPECT_EQ(v->line, 2);
  EXPECT_EQ(doc.origin(), (kData / "with_include.ini").string());
}

TEST(IniDocument, MissingIncludeIsAnError) {
  EXPECT_EQ(loadError(kData / "missing_include.ini"),
            (kData / "missing_include.ini").string() +
                ":4: @include 'does_not_exist.ini': cannot open file");
  EXPECT_EQ(parseError("[A]\n@include\n"), "cfg.ini:2: @include without a file name");
}

TEST(IniDocument, IncludeCycleIsAnError) {
  const std::string msg = loadError(kData / "cycle_a.ini");
  EXPECT_NE(msg.find("cycle_b.ini:3: @include 'cycle_a.ini': include cycle"), std::string::npos)
      << msg;
}

TEST(IniDocument, DuplicateKeyAcrossFilesNamesTheFirstFile) {
  const fs::path dir = tmpDir("dup");
  std::ofstream(dir / "base.ini") << "[S]\nsigma_m = 1\n";
  std::ofstream(dir / "main.ini") << "@define NAME base\n@include ${NAME}.ini\n\nsigma_m = 2\n";
  EXPECT_EQ(loadError(dir / "main.ini"), (dir / "main.ini").string() +
                                             ":4: duplicate key 'sigma_m' in [S] (first at " +
                                             (dir / "base.ini").string() + ":2)");
  std::ofstream(dir / "self.ini") << "[S]\n@include self.ini\n";
  EXPECT_NE(loadError(dir / "self.ini").find("self.ini:2: @include 'self.ini': include cycle"),
            std::string::npos);
}

TEST(IniDocument, IncludeDepthIsLimited) {
  const fs::path dir = tmpDir("depth");
  for (int i = 0; i < 30; ++i) {
    std::ofstream(dir / ("f" + std::to_string(i) + ".ini"))
        << "[S" << i << "]\nk = 1\n@include f" << i + 1 << ".ini\n";
  }
  std::ofstream(dir / "f30.ini") << "[End]\n";
  const std::string msg = loadError(dir / "f0.ini");
  EXPECT_NE(msg.find("includes nested deeper than 16 levels"), std::string::npos) << msg;
}

TEST(IniDocument, ParseResolvesIncludesAgainstBaseDir) {
  const auto doc = IniDocument::parse("[X]\n@include included/common.ini\n", "text", kData);
  EXPECT_EQ(valueOf(doc, "X", "min_points"), "12");
  EXPECT_EQ(valueOf(doc, "Sensors", "label"), "LASER1");
}

TEST(IniDocument, DefineSubstitutesLaterValues) {
  const auto doc = IniDocument::parse(
      "@define DIR /data/run 1  ; comment\n[S]\npath = ${DIR}/log.txt\nq = \"${DIR}\"\n"
      "env = $env{HOME}\n",
      "cfg.ini");
  EXPECT_EQ(valueOf(doc, "S", "path"), "/data/run 1/log.txt");
  EXPECT_EQ(valueOf(doc, "S", "q"), "/data/run 1");
  EXPECT_EQ(valueOf(doc, "S", "env"), "$env{HOME}");
}

TEST(IniDocument, DirectiveErrors) {
  EXPECT_EQ(parseError("[S]\na = ${NOPE}\n"),
            "cfg.ini:2: undefined variable '${NOPE}' (no @define NOPE above)");
  EXPECT_NE(parseError("[S]\na = ${OPEN\n").find("cfg.ini:2: unterminated '${'"),
            std::string::npos);
  EXPECT_EQ(parseError("@foo bar\n"),
            "cfg.ini:1: unknown directive '@foo' (expected @include or @define)");
  EXPECT_NE(parseError("@define\n").find("cfg.ini:1: malformed line '@define'"), std::string::npos);
}

TEST(IniDocument, RandomBytesParseOrFailCleanly) {
  std::mt19937 rng(12345);
  const char raw[] = "[]=;#/@\"\\${} \t\r\nabcS01.\xef\xbb\xbf\0";
  const std::string alphabet(raw, sizeof(raw) - 1);  // keeps the NUL byte
  const fs::path dir = tmpDir("fuzz");
  for (int round = 0; round < 2000; ++round) {
    std::string text;
    const int n = static_cast<int>(rng() % 80);
    for (int i = 0; i < n; ++i) {
      text += alphabet[rng() % alphabet.size()];
    }
    try {
      const auto doc = IniDocument::parse(text, "fuzz.ini", dir);
      for (const auto& s : doc.sectionNames()) {
        for (const auto& k : doc.keys(s)) {
          ASSERT_NE(doc.find(s, k), nullptr);
        }
      }
    } catch (const ConfigError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("fuzz.ini", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace pmap::config
