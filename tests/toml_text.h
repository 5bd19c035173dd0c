#pragma once
// Loading scene text in tests, and checking the SceneError a mistake gives.

#include "glint/scene_format/toml_scene_loader.h"
#include "source_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace glint {
namespace {

/// A material named "red" with every other field at its default, for texts that need one.
constexpr std::string_view kRed = "[[materials]]\nname = \"red\"\n";

LoadedScene load(std::string_view text) { return load_toml_scene_string(text, "test.toml", glint_test::kScenesDir); }

/// The SceneError message for `text`, or a test failure if it loads.
std::string error_of(std::string_view text) {
    try {
        (void)load(text);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a SceneError for:\n" << text;
    return {};
}

/// The message starts with `location` ("test.toml:line:column:") and contains every word.
void expect_error(std::string_view text, const std::string& location, std::initializer_list<std::string> words) {
    const std::string message = error_of(text);
    EXPECT_EQ(message.rfind(location, 0), 0u) << "expected the message to start with " << location << ":\n" << message;
    for (const std::string& w : words)
        EXPECT_NE(message.find(w), std::string::npos) << "missing '" << w << "' in:\n" << message;
}

}  // namespace
}  // namespace glint
