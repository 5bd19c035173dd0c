// Finding the [[objects]] entries of TOML text by its lines (src/scene_format/toml_entries.h):
// every entry whole, from its header to the next header that is not its own; nothing taken
// from inside a string or a value that spans lines; the rest keeping every line's number.

#include "scene_format/toml_entries.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glint {
namespace {

std::vector<std::string> texts(const TomlEntries& split) {
    std::vector<std::string> out;
    for (const TomlEntry& entry : split.entries) out.emplace_back(entry.text);
    return out;
}

std::size_t lines(std::string_view text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }

TEST(TomlEntries, EachEntryRunsToTheNextHeaderThatIsNotItsOwn) {
    const std::string text =
        "title = 1\n"
        "[[objects]]\n"
        "type = \"sphere\"\n"
        "[objects.transform]\n"
        "scale = 2\n"
        "[[objects.motion]]\n"
        "time = 0\n"
        "[camera]\n"
        "fov = 30\n"
        "  [[ objects ]]  # indented, spaced, commented\n"
        "type = \"quad\"\n";
    const TomlEntries split = split_toml_entries(text, "objects");
    EXPECT_EQ(texts(split),
              (std::vector<std::string>{"[[objects]]\ntype = \"sphere\"\n[objects.transform]\nscale = 2\n"
                                        "[[objects.motion]]\ntime = 0\n",
                                        "  [[ objects ]]  # indented, spaced, commented\ntype = \"quad\"\n"}));
    ASSERT_EQ(split.entries.size(), 2u);
    EXPECT_EQ(split.entries[0].first_line, 2u);
    EXPECT_EQ(split.entries[1].first_line, 10u);
    EXPECT_EQ(split.rest, "title = 1\n\n\n\n\n\n\n[camera]\nfov = 30\n\n\n");
}

TEST(TomlEntries, TheRestKeepsLineNumbersAndColumnsWithCrLfAndNoFinalLineBreak) {
    const std::string text = "[[objects]]\r\na = 1\r\n[render]\r\nwidth = 2\r\n[[objects]]\r\nb = 2";
    const TomlEntries split = split_toml_entries(text, "objects");
    EXPECT_EQ(texts(split), (std::vector<std::string>{"[[objects]]\r\na = 1\r\n", "[[objects]]\r\nb = 2"}));
    EXPECT_EQ(split.rest, "\n\n[render]\r\nwidth = 2\r\n\n");
    EXPECT_EQ(lines(split.rest), lines(text));
}

TEST(TomlEntries, OtherNamesAndOtherKindsOfHeaderAreNotEntries) {
    for (const std::string header : {"[objects]", "[[objects_2]]", "[[objectsx]]", "[[\"objects\"]]", "[lights]"}) {
        const std::string text = header + "\na = 1\n";
        const TomlEntries split = split_toml_entries(text, "objects");
        EXPECT_TRUE(split.entries.empty()) << header;
        EXPECT_EQ(split.rest, text) << header;
    }
    // A header below an entry that follows another section stays in the rest (where the
    // loader sees `objects` and parses the file whole).
    const std::string text = "[[objects]]\na = 1\n[camera]\n[objects.transform]\nscale = 2\n";
    const TomlEntries split = split_toml_entries(text, "objects");
    EXPECT_EQ(texts(split), (std::vector<std::string>{"[[objects]]\na = 1\n"}));
    EXPECT_EQ(split.rest, "\n\n[camera]\n[objects.transform]\nscale = 2\n");
}

TEST(TomlEntries, NothingIsTakenFromInsideMultiLineStrings) {
    for (const std::string quotes : {"\"\"\"", "'''"}) {
        const std::string text = "[[materials]]\nname = " + quotes + "\n[[objects]]\n[camera]\n" + quotes +
                                 "\n[[objects]]\nname = " + quotes + "a\n[camera]" + quotes + "\n[render]\n";
        const TomlEntries split = split_toml_entries(text, "objects");
        EXPECT_EQ(texts(split),
                  (std::vector<std::string>{"[[objects]]\nname = " + quotes + "a\n[camera]" + quotes + "\n"}))
            << quotes;
    }
    // Up to two quotes right before the closing three belong to the string; an escaped
    // quote does not close a basic string, nor does a string inside a comment open one.
    const std::string text =
        "[[objects]]\n"
        "a = \"\"\"x\"\"\"\"\"  # five quotes: x\"\" and the end\n"
        "b = \"\"\"y\\\"\"\"\n"
        "[[objects]]\n"
        "\"\"\"\n"
        "c = [\"\\\"\", 1]\n"
        "d = [\"\"\"x\"\"\"\", 1, '''y'''', 2]\n"
        "# \"\"\" in a comment\n"
        "[[objects]]\n";
    const TomlEntries split = split_toml_entries(text, "objects");
    EXPECT_EQ(texts(split),
              (std::vector<std::string>{"[[objects]]\na = \"\"\"x\"\"\"\"\"  # five quotes: x\"\" and the end\n"
                                        "b = \"\"\"y\\\"\"\"\n[[objects]]\n\"\"\"\nc = [\"\\\"\", 1]\n"
                                        "d = [\"\"\"x\"\"\"\", 1, '''y'''', 2]\n"
                                        "# \"\"\" in a comment\n",
                                        "[[objects]]\n"}))
        << "the second entry's value y\\\"\"\" closes on the line with the lone \"\"\"";
    EXPECT_EQ(split.entries.back().first_line, 9u);
}

TEST(TomlEntries, NothingIsTakenFromInsideValuesThatSpanLines) {
    const std::string text =
        "[[objects]]\n"
        "positions = [\n"
        "  [0, 0, 0],\n"
        "[1, 0, 0], # ]]\n"
        "  [0, \"]\", 1],\n"
        "]\n"
        "[[objects]]\n"
        "name = \"[ {\"\n"
        "[render]\n";
    const TomlEntries split = split_toml_entries(text, "objects");
    EXPECT_EQ(texts(split), (std::vector<std::string>{
                                "[[objects]]\npositions = [\n  [0, 0, 0],\n[1, 0, 0], # ]]\n  [0, \"]\", 1],\n]\n",
                                "[[objects]]\nname = \"[ {\"\n"}));
    EXPECT_EQ(split.rest, "\n\n\n\n\n\n\n\n[render]\n");
}

}  // namespace
}  // namespace glint
