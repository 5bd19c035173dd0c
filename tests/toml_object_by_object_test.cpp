// The TOML loader reads [[objects]] one at a time (src/scene_format/toml_entries.h): a file
// means the same and fails at the same place as if it were parsed whole, wherever its
// objects stand among the other sections, and valid TOML that cannot be read in entries
// (a header of an object after another section, an inline `objects = [...]`) is read whole;
// so is a file with a syntax error anywhere, which is the mistake it reports first.

#include "toml_text.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

/// The centre of object `index`'s world bounds along x.
float centre_x(const LoadedScene& loaded, std::size_t index) {
    const Bounds3 box = loaded.scene.objects().at(index).world_bounds();
    return 0.5f * (box.lo.x + box.hi.x);
}

TEST(TomlObjectByObject, ObjectsAmongOtherSectionsLandAsWritten) {
    const LoadedScene loaded = load(
        "[[objects]]\n"
        "name = \"first\"\n"
        "type = \"sphere\"\n"
        "radius = 1\n"
        "material = \"red\"  # defined further down\n"
        "[objects.transform]\n"
        "translate = [5, 0, 0]\n"
        "[render]\n"
        "width = 8\n"
        "[[objects]]\n"
        "name = \"second \\\"[[objects]]\\\"\"\n"
        "type = \"sphere\"\n"
        "radius = 1\n"
        "material = \"red\"\n"
        "transform = { translate = [\n"
        "  -3,\n"
        "  0, 0] }\n"
        "[[materials]]\n"
        "name = \"red\"\n"
        "[[lights]]\n"
        "type = \"point\"\n"
        "position = [0, 5, 0]\n");
    ASSERT_EQ(loaded.scene.objects().size(), 2u);
    EXPECT_EQ(loaded.scene.objects()[0].name, "first");
    EXPECT_EQ(loaded.scene.objects()[1].name, "second \"[[objects]]\"");
    EXPECT_FLOAT_EQ(centre_x(loaded, 0), 5.0f);
    EXPECT_FLOAT_EQ(centre_x(loaded, 1), -3.0f);
    EXPECT_EQ(loaded.settings.width, 8u);
    EXPECT_EQ(loaded.scene.lights().size(), 1u);
}

TEST(TomlObjectByObject, ValidTomlThatEntriesCannotCarryIsReadWhole) {
    // The table of the first object's transform, written after another section.
    const LoadedScene later_table = load(
        "[[materials]]\nname = \"red\"\n"
        "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n"
        "[render]\nwidth = 8\n"
        "[objects.transform]\ntranslate = [7, 0, 0]\n");
    ASSERT_EQ(later_table.scene.objects().size(), 1u);
    EXPECT_FLOAT_EQ(centre_x(later_table, 0), 7.0f);

    const LoadedScene inline_array = load(
        "objects = [{ type = \"sphere\", radius = 1, material = \"red\" }, { type = \"sphere\", radius = 1, material = "
        "\"red\", "
        "transform = { translate = [2, 0, 0] } }]\n"
        "[[materials]]\nname = \"red\"\n");
    ASSERT_EQ(inline_array.scene.objects().size(), 2u);
    EXPECT_FLOAT_EQ(centre_x(inline_array, 1), 2.0f);
}

TEST(TomlObjectByObject, MistakesAreLocatedInTheWholeFile) {
    const std::string head =
        "[[materials]]\nname = \"red\"\n"
        "[[objects]]\ntype = \"sphere\"\nradius = 1\nmaterial = \"red\"\n"
        "[render]\nwidth = 8\n";
    // Line 9 onwards is the second object.
    const std::string sphere = "[[objects]]\ntype = \"sphere\"\n";
    expect_error(head + sphere + "radius = 1\nmaterial = \"red\"\n[objects.transform]\nscale = 0\n",
                 "test.toml:14:9:", {"objects[1].transform.scale", "\n 14 | scale = 0\n"});
    expect_error(head + sphere + "radius = -1\nmaterial = \"red\"\n", "test.toml:11:10:", {"objects[1].radius is -1"});
    expect_error(head + sphere + "radius = \nmaterial = \"red\"\n",
                 "test.toml:11:", {"invalid TOML", "\n 11 | radius = \n"});
    expect_error(head + sphere + "type = \"quad\"\n", "test.toml:11:", {"invalid TOML"});
    expect_error(head + sphere + "radius = 1\ncolor = 1\nmaterial = \"red\"\n",
                 "test.toml:12:1:", {"unknown key 'color'", "objects[1]"});
    // Parsed whole, a syntax error anywhere comes first, before a wrong value above it.
    expect_error(head + sphere + "radius = -1\nmaterial = \"red\"\n" + sphere + "radius = \n",
                 "test.toml:15:", {"invalid TOML"});
    std::string wrong_width = head;
    wrong_width.replace(wrong_width.find("width = 8"), 9, "width = 0");
    expect_error(wrong_width + sphere + "radius = \n", "test.toml:11:", {"invalid TOML"});
    expect_error(wrong_width + sphere + "radius = 1\nmaterial = \"red\"\n", "test.toml:8:9:", {"render.width"});
    // A mistake in a section after the objects, and an array that is also a table.
    expect_error(head + sphere + "radius = 1\nmaterial = \"red\"\n[camera\n", "test.toml:13:8:", {"invalid TOML"});
    expect_error("objects = []\n" + head, "test.toml:4:", {"invalid TOML"});
}

}  // namespace
}  // namespace glint
