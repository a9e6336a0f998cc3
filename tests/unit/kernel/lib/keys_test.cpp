// Scan code set 1 decoding and the show's bindings (kernel/lib/keys.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel/lib/keys.h"

namespace {

using lib::Key;

std::vector<std::string> decode(const std::vector<uint8_t>& bytes) {
    lib::ScanDecoder d;
    std::vector<std::string> out;
    for (uint8_t b : bytes) {
        lib::KeyEvent e;
        if (d.feed(b, &e)) out.push_back(std::string(e.pressed ? "+" : "-") + lib::key_name(e.key));
    }
    return out;
}

TEST(Keys, MakeAndBreakCodesOfTheFirstBank) {
    EXPECT_EQ(decode({0x39, 0xB9}), (std::vector<std::string>{"+space", "-space"}));
    EXPECT_EQ(decode({0x23, 0x1F, 0x2F, 0x3B, 0x01, 0x0D, 0x0C, 0x4E, 0x4A, 0x58}),
              (std::vector<std::string>{"+h", "+s", "+v", "+f1", "+escape", "+equals", "+minus", "+keypad-plus", "+keypad-minus", "+f12"}));
    // every letter row in order
    std::vector<std::string> letters;
    for (const char* row : {"qwertyuiop", "asdfghjkl", "zxcvbnm"})
        for (const char* c = row; *c; ++c) letters.push_back(std::string("+") + *c);
    EXPECT_EQ(decode({0x10, 0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18, 0x19, 0x1E, 0x1F, 0x20, 0x21, 0x22, 0x23, 0x24, 0x25,
                      0x26, 0x2C, 0x2D, 0x2E, 0x2F, 0x30, 0x31, 0x32}),
              letters);
}

TEST(Keys, TheSecondBankAfterE0) {
    EXPECT_EQ(decode({0xE0, 0x48, 0xE0, 0xC8, 0xE0, 0x50, 0xE0, 0x4B, 0xE0, 0x4D, 0xE0, 0x49, 0xE0, 0x51, 0xE0, 0x1C}),
              (std::vector<std::string>{"+up", "-up", "+down", "+left", "+right", "+page-up", "+page-down", "+keypad-enter"}));
    // the keypad's 8 without E0 is not the arrow; the fake shifts around an arrow are no keys
    EXPECT_EQ(decode({0x48, 0xE0, 0x2A, 0xE0, 0x48, 0xE0, 0xC8, 0xE0, 0xAA}), (std::vector<std::string>{"+up", "-up"}));
    // a prefix applies to one byte only
    EXPECT_EQ(decode({0xE0, 0x48, 0x48}), (std::vector<std::string>{"+up"}));
}

TEST(Keys, PauseAndTheControllersOwnBytesAreNoKeys) {
    EXPECT_EQ(decode({0xE1, 0x1D, 0x45, 0xE1, 0x9D, 0xC5, 0x39}), (std::vector<std::string>{"+space"}));
    EXPECT_EQ(decode({0xFA, 0xFE, 0x00, 0xFF, 0x39}), (std::vector<std::string>{"+space"}));
    EXPECT_EQ(decode({0x1D, 0x2A, 0x36, 0x38, 0x3A, 0x45, 0x46, 0x7F}), (std::vector<std::string>{})) << "modifiers and locks are not bound";
}

TEST(Keys, EveryBindingIsInTheHelpAndEveryHelpKeyIsBound) {
    // the bindings as the help writes them: each key named there does what the line says
    const std::vector<std::pair<Key, lib::Action>> bound = {
        {Key::Right, lib::Action::NextScene}, {Key::N, lib::Action::NextScene},       {Key::Left, lib::Action::PreviousScene},
        {Key::P, lib::Action::PreviousScene}, {Key::Down, lib::Action::NextMapper},   {Key::M, lib::Action::NextMapper},
        {Key::Up, lib::Action::PreviousMapper}, {Key::Equals, lib::Action::BudgetUp}, {Key::KeypadPlus, lib::Action::BudgetUp},
        {Key::Minus, lib::Action::BudgetDown}, {Key::KeypadMinus, lib::Action::BudgetDown}, {Key::Space, lib::Action::Pause},
        {Key::S, lib::Action::Step},          {Key::Period, lib::Action::Step},       {Key::V, lib::Action::Surface},
        {Key::H, lib::Action::Hud},           {Key::F1, lib::Action::Help},           {Key::Slash, lib::Action::Help},
        {Key::B, lib::Action::Bench},
    };
    for (auto [k, a] : bound) EXPECT_EQ(lib::action_for(k), a) << lib::key_name(k);
    EXPECT_EQ(lib::action_for(Key::Q), lib::Action::None);
    EXPECT_EQ(lib::action_for(Key::None), lib::Action::None);
    std::string help;
    for (int i = 0; i < lib::help_line_count(); ++i) help += std::string(lib::help_line(i)) + "\n";
    for (const char* line : {"Right N     next scene", "Space       pause, go on", "F1 ?        this help", "B           the bench, on this PC", "any key: back to the show"})
        EXPECT_NE(help.find(line), std::string::npos) << line << " in\n" << help;
    for (int i = 0; i < lib::help_line_count(); ++i) EXPECT_LE(std::string(lib::help_line(i)).size(), 39u) << "within the screen's 40 columns";
}

}  // namespace
