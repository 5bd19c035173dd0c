#pragma once
// The viewer's window as it shows, to a PNG (the `screenshot` step of a scripted session).

#include <SDL.h>

#include <string>

namespace glint::app {

/// Read the OpenGL back buffer of `window` (call after drawing, before the swap) and write
/// it to `path`; prints "screenshot PATH" or why it could not.
void write_screenshot(SDL_Window* window, const std::string& path);

}  // namespace glint::app
