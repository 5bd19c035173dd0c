#pragma once
// A scripted viewer session, for tests and demos: what a user would do, one step per line
// (or separated by ';'), fed to the window as SDL events so that the same handlers run.
//
//   wait converged        until every pass of the sample budget is in
//   wait passes N         until N full-resolution passes are in
//   wait frames N         N frames (lets a coarse frame show)
//   key NAME              press and release a key: a letter, escape
//   drag BUTTON DX DY     left, middle or right button, from the image centre, in pixels
//   wheel N               N notches (negative: towards the user)
//   click X Y             left click on image pixel (X, Y)
//   show VIEW             image, or a heatmap: nodes, primitives, shadow, depth
//   save PATH             write the accumulated image (EXR/PNG by extension)
//   screenshot PATH       write the window as it shows (PNG)
//   quit                  close the window

#include <cstdint>
#include <string>
#include <vector>

namespace glint::app {

struct ScriptStep {
    enum class Kind { WaitConverged, WaitPasses, WaitFrames, Key, Drag, Wheel, Click, Show, Save, Screenshot, Quit };
    Kind kind = Kind::Quit;
    std::string text;  ///< key name, button name or path
    int32_t a = 0, b = 0;
};

/// The steps of `script`. Throws std::invalid_argument "--script: step N ('...'): expected ..."
/// for a step it cannot read.
[[nodiscard]] std::vector<ScriptStep> parse_session_script(const std::string& script);

/// Queue the SDL events a user would cause for a key, drag, wheel or click step: drags start
/// at window point (centre_x, centre_y), clicks land on the centre of image pixel (X, Y) of an
/// image shown `scale` window pixels per image pixel.
void push_script_events(const ScriptStep& step, int centre_x, int centre_y, float scale);

}  // namespace glint::app
