// The options the chapters declared (options.hpp), offered on a CLI11 command: the renderer's
// `render` command offers them all, a benchmark only those of one target (the accelerators').
#pragma once

#include "freezeray/options.hpp"

#include <CLI/CLI.hpp>

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace freezeray {

// The options the chapters declared, on one command: each stored in a slot of its type, turned
// into OptionValues after parsing. `--help` lists them under their chapter.
class ChapterOptions {
public:
    // Adds each declaration (of `only`'s target, when given) to `command`.
    void declare(CLI::App& command, const std::vector<OptionDeclaration>& declarations,
                 std::optional<OptionTarget> only = std::nullopt) {
        for (const OptionDeclaration& d : declarations) {
            if (only && d.target != *only) continue;
            Slot& slot = slots_.emplace_back();
            slot.declaration = &d;
            const std::string group = std::string("Options of chapter ") + (d.chapter < 10 ? "0" : "") + std::to_string(d.chapter);
            switch (d.type) {
                case OptionType::Number: slot.option = command.add_option(d.flag, slot.number, d.help); break;
                case OptionType::Integer: slot.option = command.add_option(d.flag, slot.integer, d.help); break;
                case OptionType::Text: slot.option = command.add_option(d.flag, slot.text, d.help); break;
                case OptionType::Flag: slot.option = command.add_flag(d.flag, slot.flag, d.help); break;
            }
            slot.option->group(group);
        }
    }

    OptionValues values() const {
        OptionValues values;
        for (const Slot& slot : slots_) {
            if (slot.option->count() == 0) continue;
            const OptionDeclaration& d = *slot.declaration;
            switch (d.type) {
                case OptionType::Number: values.values[d.key] = slot.number; break;
                case OptionType::Integer: values.values[d.key] = slot.integer; break;
                case OptionType::Text: values.values[d.key] = slot.text; break;
                case OptionType::Flag: values.values[d.key] = slot.flag; break;
            }
            values.flags[d.key] = d.flag;
        }
        return values;
    }

private:
    struct Slot {
        const OptionDeclaration* declaration = nullptr;
        CLI::Option* option = nullptr;
        double number = 0.0;
        long long integer = 0;
        std::string text;
        bool flag = false;
    };
    std::deque<Slot> slots_;  // a deque: CLI11 keeps pointers to the slots' values
};

}  // namespace freezeray
