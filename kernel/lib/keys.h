// The keyboard as the show reads it: PC scan code set 1 (what the 8042 hands over with translation
// on) decoded into keys, and the show's key bindings, from which its help screen is written.
// Portable: the host tests the decoder and draws the same help.
#pragma once

#include <stdint.h>

namespace lib {

enum class Key : uint8_t {
    None,
    Escape, Enter, Space, Tab, Backspace,
    Up, Down, Left, Right, PageUp, PageDown, Home, End, Insert, Delete,
    F1, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12,
    Minus, Equals, Slash, Comma, Period,
    KeypadPlus, KeypadMinus, KeypadEnter,
    Digit0, Digit1, Digit2, Digit3, Digit4, Digit5, Digit6, Digit7, Digit8, Digit9,
    A, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
};
const char* key_name(Key k);  // "space", "left", "f1", "h", ...

struct KeyEvent {
    Key key = Key::None;
    bool pressed = false;  // false: released
};

// Set 1: a make code is the key's code, its break code the same with bit 7 set; 0xE0 prefixes the
// second bank (arrows, the navigation block, the keypad's Enter); 0xE1 starts Pause's six bytes,
// which carry no release. Bytes the controller sends for itself (0x00 and 0xFF: errors, 0xFA: an
// acknowledgement, 0xFE: resend) are not keys.
class ScanDecoder {
public:
    // Feeds one byte; true with *out set when it completed a key's press or release.
    bool feed(uint8_t byte, KeyEvent* out);

private:
    bool extended_ = false;
    uint8_t skip_ = 0;  // bytes of a Pause sequence still to come
};

// What a key does in the show (kernel/show/show.cpp).
enum class Action : uint8_t {
    None, NextScene, PreviousScene, NextMapper, PreviousMapper, BudgetUp, BudgetDown,
    Pause, Step, Surface, Hud, Help, Bench,
};
const char* action_name(Action a);  // "next-scene", ...
Action action_for(Key k);

// The help screen: one line a binding ("Right N     next scene"), then how to leave it.
int help_line_count();
const char* help_line(int i);

}  // namespace lib
