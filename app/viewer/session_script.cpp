#include "session_script.h"

#include <SDL.h>
#include <fmt/core.h>

#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>

namespace glint::app {

namespace {

std::vector<std::string> words(const std::string& step) {
    std::istringstream in(step);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

}  // namespace

std::vector<ScriptStep> parse_session_script(const std::string& script) {
    std::vector<ScriptStep> steps;
    std::string text = script;
    for (char& c : text)
        if (c == ';') c = '\n';
    std::istringstream lines(text);
    std::size_t number = 0;
    for (std::string line; std::getline(lines, line);) {
        const std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        ++number;
        auto fail = [&](const char* expected) {
            return std::invalid_argument(fmt::format("--script: step {} ('{}'): expected {}", number, line, expected));
        };
        auto integer = [&](std::size_t i, const char* expected) {
            int32_t v = 0;
            if (i >= w.size()) throw fail(expected);
            const auto [end, error] = std::from_chars(w[i].data(), w[i].data() + w[i].size(), v);
            if (error != std::errc() || end != w[i].data() + w[i].size()) throw fail(expected);
            return v;
        };
        ScriptStep s;
        const std::string& verb = w[0];
        if (verb == "wait") {
            if (w.size() == 2 && w[1] == "converged") {
                s.kind = ScriptStep::Kind::WaitConverged;
            } else if (w.size() == 3 && (w[1] == "passes" || w[1] == "frames")) {
                s.kind = w[1] == "passes" ? ScriptStep::Kind::WaitPasses : ScriptStep::Kind::WaitFrames;
                s.a = integer(2, "wait converged, wait passes N or wait frames N");
            } else {
                throw fail("wait converged, wait passes N or wait frames N");
            }
        } else if (verb == "key") {
            // The keys the viewer answers to: letters (F, R, P, S, and W A S D Q E to fly) and Escape.
            const bool letter = w.size() == 2 && w[1].size() == 1 && std::isalpha(static_cast<unsigned char>(w[1][0]));
            if (!letter && !(w.size() == 2 && w[1] == "escape")) throw fail("key NAME, a letter or escape");
            s.kind = ScriptStep::Kind::Key;
            s.text = w[1];
        } else if (verb == "drag" && w.size() == 4 && (w[1] == "left" || w[1] == "middle" || w[1] == "right")) {
            s.kind = ScriptStep::Kind::Drag;
            s.text = w[1];
            s.a = integer(2, "drag left|middle|right DX DY");
            s.b = integer(3, "drag left|middle|right DX DY");
        } else if (verb == "wheel" && w.size() == 2) {
            s.kind = ScriptStep::Kind::Wheel;
            s.a = integer(1, "wheel N");
        } else if (verb == "click" && w.size() == 3) {
            s.kind = ScriptStep::Kind::Click;
            s.a = integer(1, "click X Y");
            s.b = integer(2, "click X Y");
        } else if (verb == "show") {
            if (w.size() != 2 ||
                (w[1] != "image" && w[1] != "nodes" && w[1] != "primitives" && w[1] != "shadow" && w[1] != "depth"))
                throw fail("show image, nodes, primitives, shadow or depth");
            s.kind = ScriptStep::Kind::Show;
            s.text = w[1];
        } else if ((verb == "save" || verb == "screenshot") && w.size() == 2) {
            s.kind = verb == "save" ? ScriptStep::Kind::Save : ScriptStep::Kind::Screenshot;
            s.text = w[1];
        } else if (verb == "quit" && w.size() == 1) {
            s.kind = ScriptStep::Kind::Quit;
        } else {
            throw fail("wait, key, drag, wheel, click, show, save, screenshot or quit with their arguments");
        }
        steps.push_back(std::move(s));
    }
    return steps;
}

void push_script_events(const ScriptStep& step, int centre_x, int centre_y, float scale) {
    auto push = [](SDL_Event e) { SDL_PushEvent(&e); };
    auto button = [&](Uint32 type, Uint8 which, int x, int y) {
        SDL_Event e{};
        e.type = type;
        e.button.button = which;
        e.button.x = x;
        e.button.y = y;
        push(e);
    };
    const int cx = centre_x, cy = centre_y;
    if (step.kind == ScriptStep::Kind::Key) {
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.keysym.sym = SDL_GetKeyFromName(step.text.c_str());
        push(e);
        e.type = SDL_KEYUP;
        push(e);
    } else if (step.kind == ScriptStep::Kind::Drag) {
        const Uint8 which = step.text == "left"     ? SDL_BUTTON_LEFT
                            : step.text == "middle" ? SDL_BUTTON_MIDDLE
                                                    : SDL_BUTTON_RIGHT;
        button(SDL_MOUSEBUTTONDOWN, which, cx, cy);
        SDL_Event e{};
        e.type = SDL_MOUSEMOTION;
        e.motion.x = cx + step.a;
        e.motion.y = cy + step.b;
        e.motion.xrel = step.a;
        e.motion.yrel = step.b;
        push(e);
        button(SDL_MOUSEBUTTONUP, which, cx + step.a, cy + step.b);
    } else if (step.kind == ScriptStep::Kind::Wheel) {
        SDL_Event e{};
        e.type = SDL_MOUSEWHEEL;
        e.wheel.y = step.a;
        push(e);
    } else if (step.kind == ScriptStep::Kind::Click) {
        const int x = int((float(step.a) + 0.5f) * scale), y = int((float(step.b) + 0.5f) * scale);
        button(SDL_MOUSEBUTTONDOWN, SDL_BUTTON_LEFT, x, y);
        button(SDL_MOUSEBUTTONUP, SDL_BUTTON_LEFT, x, y);
    }
}

}  // namespace glint::app
