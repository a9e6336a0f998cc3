// Scan code set 1 and the show's bindings (keys.h).
#include "kernel/lib/keys.h"

namespace lib {

namespace {

constexpr const char* KEY_NAMES[] = {
    "none", "escape", "enter", "space", "tab", "backspace",
    "up", "down", "left", "right", "page-up", "page-down", "home", "end", "insert", "delete",
    "f1", "f2", "f3", "f4", "f5", "f6", "f7", "f8", "f9", "f10", "f11", "f12",
    "minus", "equals", "slash", "comma", "period",
    "keypad-plus", "keypad-minus", "keypad-enter",
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9",
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q", "r", "s", "t", "u", "v", "w", "x", "y", "z",
};
static_assert(sizeof(KEY_NAMES) / sizeof(KEY_NAMES[0]) == int(Key::Z) + 1);

// Set 1 make codes 0x00..0x58 (the first bank); None where the key is not one the show knows.
constexpr Key BANK0[0x59] = {
    Key::None, Key::Escape, Key::Digit1, Key::Digit2, Key::Digit3, Key::Digit4, Key::Digit5, Key::Digit6,          // 00
    Key::Digit7, Key::Digit8, Key::Digit9, Key::Digit0, Key::Minus, Key::Equals, Key::Backspace, Key::Tab,        // 08
    Key::Q, Key::W, Key::E, Key::R, Key::T, Key::Y, Key::U, Key::I,                                                // 10
    Key::O, Key::P, Key::None, Key::None, Key::Enter, Key::None, Key::A, Key::S,                                  // 18 ([ ] Ctrl)
    Key::D, Key::F, Key::G, Key::H, Key::J, Key::K, Key::L, Key::None,                                            // 20 (;)
    Key::None, Key::None, Key::None, Key::None, Key::Z, Key::X, Key::C, Key::V,                                   // 28 (' ` LShift \)
    Key::B, Key::N, Key::M, Key::Comma, Key::Period, Key::Slash, Key::None, Key::None,                            // 30 (RShift, keypad *)
    Key::None, Key::Space, Key::None, Key::F1, Key::F2, Key::F3, Key::F4, Key::F5,                                // 38 (Alt, Caps Lock)
    Key::F6, Key::F7, Key::F8, Key::F9, Key::F10, Key::None, Key::None, Key::None,                                // 40 (Num Lock, Scroll Lock, keypad 7)
    Key::None, Key::None, Key::KeypadMinus, Key::None, Key::None, Key::None, Key::KeypadPlus, Key::None,          // 48 (keypad 8 9 - 4 5 6 + 1)
    Key::None, Key::None, Key::None, Key::None, Key::None, Key::None, Key::None, Key::F11,                        // 50 (keypad 2 3 0 ., 54-56)
    Key::F12,                                                                                                      // 58
};

// The second bank (after 0xE0): the keys the show knows; the rest, and the fake shifts some
// keyboards wrap around them (E0 2A, E0 36), are None.
Key bank1(uint8_t code) {
    switch (code) {
    case 0x1C: return Key::KeypadEnter;
    case 0x47: return Key::Home;
    case 0x48: return Key::Up;
    case 0x49: return Key::PageUp;
    case 0x4B: return Key::Left;
    case 0x4D: return Key::Right;
    case 0x4F: return Key::End;
    case 0x50: return Key::Down;
    case 0x51: return Key::PageDown;
    case 0x52: return Key::Insert;
    case 0x53: return Key::Delete;
    default: return Key::None;
    }
}

struct Binding {
    Action action;
    Key keys[3];  // None-terminated
    const char* keys_text;
    const char* what;
};
constexpr Binding BINDINGS[] = {
    {Action::NextScene, {Key::Right, Key::N, Key::None}, "Right N", "next scene"},
    {Action::PreviousScene, {Key::Left, Key::P, Key::None}, "Left P", "previous scene"},
    {Action::NextMapper, {Key::Down, Key::M, Key::None}, "Down M", "next mapper"},
    {Action::PreviousMapper, {Key::Up, Key::None, Key::None}, "Up", "previous mapper"},
    {Action::BudgetUp, {Key::Equals, Key::KeypadPlus, Key::None}, "+ =", "auto: larger budget"},
    {Action::BudgetDown, {Key::Minus, Key::KeypadMinus, Key::None}, "-", "auto: smaller budget"},
    {Action::Pause, {Key::Space, Key::None, Key::None}, "Space", "pause, go on"},
    {Action::Step, {Key::S, Key::Period, Key::None}, "S .", "one frame, paused"},
    {Action::Surface, {Key::V, Key::None, Key::None}, "V", "RAM + blit / VGA memory"},
    {Action::Hud, {Key::H, Key::None, Key::None}, "H", "figures on / off"},
    {Action::Help, {Key::F1, Key::Slash, Key::None}, "F1 ?", "this help"},
    {Action::Bench, {Key::B, Key::None, Key::None}, "B", "the bench, on this PC"},
};
constexpr int BINDING_COUNT = sizeof(BINDINGS) / sizeof(BINDINGS[0]);

constexpr const char* ACTION_NAMES[] = {"none", "next-scene", "previous-scene", "next-mapper", "previous-mapper", "budget-up",
                                        "budget-down", "pause", "step", "surface", "hud", "help", "bench"};
static_assert(sizeof(ACTION_NAMES) / sizeof(ACTION_NAMES[0]) == int(Action::Bench) + 1);

// The help's lines, written once: "  Right N     next scene" (keys in a column of 12).
constexpr int HELP_HEAD = 2, HELP_TAIL = 2, HELP_WIDTH = 40;
constexpr int HELP_LINES = HELP_HEAD + BINDING_COUNT + HELP_TAIL;
char g_help[HELP_LINES][HELP_WIDTH] = {};
bool g_help_built = false;

void build_help() {
    auto put = [](char* line, const char* a, int column, const char* b) {
        int n = 0;
        for (; *a && n < HELP_WIDTH - 1; ++a) line[n++] = *a;
        while (n < column && n < HELP_WIDTH - 1) line[n++] = ' ';
        for (; *b && n < HELP_WIDTH - 1; ++b) line[n++] = *b;
        line[n] = 0;
    };
    put(g_help[0], "modexlab: the keys", 0, "");
    put(g_help[1], "", 0, "");
    for (int i = 0; i < BINDING_COUNT; ++i) put(g_help[HELP_HEAD + i], BINDINGS[i].keys_text, 12, BINDINGS[i].what);
    put(g_help[HELP_HEAD + BINDING_COUNT], "", 0, "");
    put(g_help[HELP_HEAD + BINDING_COUNT + 1], "any key: back to the show", 0, "");
    g_help_built = true;
}

}  // namespace

const char* key_name(Key k) { return int(k) <= int(Key::Z) ? KEY_NAMES[int(k)] : "?"; }

bool ScanDecoder::feed(uint8_t byte, KeyEvent* out) {
    if (skip_ > 0) {
        --skip_;
        return false;
    }
    if (byte == 0xE1) {  // Pause: E1 1D 45 E1 9D C5
        skip_ = 5;
        extended_ = false;
        return false;
    }
    if (byte == 0xE0) {
        extended_ = true;
        return false;
    }
    const bool extended = extended_;
    extended_ = false;
    if (byte == 0x00 || byte == 0xFF || byte == 0xFA || byte == 0xFE) return false;
    const uint8_t code = byte & 0x7F;
    const Key k = extended ? bank1(code) : code < sizeof(BANK0) / sizeof(BANK0[0]) ? BANK0[code] : Key::None;
    if (k == Key::None) return false;
    *out = KeyEvent{k, (byte & 0x80) == 0};
    return true;
}

const char* action_name(Action a) { return int(a) <= int(Action::Bench) ? ACTION_NAMES[int(a)] : "?"; }

Action action_for(Key k) {
    if (k == Key::None) return Action::None;
    for (const Binding& b : BINDINGS)
        for (Key bound : b.keys)
            if (bound == k) return b.action;
    return Action::None;
}

int help_line_count() { return HELP_LINES; }

const char* help_line(int i) {
    if (!g_help_built) build_help();
    return i >= 0 && i < HELP_LINES ? g_help[i] : "";
}

}  // namespace lib
