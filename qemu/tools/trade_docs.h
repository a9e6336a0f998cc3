// The figures the docs show, generated from a trade.csv: each block between
//   <!-- make bench: NAME -->   and   <!-- end make bench -->
// in README.md and docs/results.md is the generator's output for NAME, so that no figure there is
// typed. `make bench` refreshes them from docs/data/trade.csv; a unit test checks that the
// committed blocks are what the generator makes of the committed CSV.
#pragma once

#include <string>
#include <vector>

#include "qemu/tools/trade.h"

namespace harness {

// The files whose blocks make bench refreshes, relative to the source tree.
inline const std::vector<std::string> GENERATED_DOCS = {"README.md", "docs/results.md"};
inline constexpr const char* DOCS_TRADE_CSV = "docs/data/trade.csv";

// The README's headline: per scene, auto at the scene's budget beside the fastest single mapper
// within that budget and exact.
std::string headline_table(const std::vector<TradeRow>& rows);

// What auto drew each scene with at the scene's budget: a list item a scene.
std::string choices_list(const std::vector<TradeRow>& rows);

// What NAME's block holds: "headline"; "scene S" (scene_table); "same-work S" (same_work_table);
// "auto" (every auto row) or "auto at scene budgets"; "choices". HarnessError for an unknown name or a block
// the rows cannot fill.
std::string generated_block(const std::string& name, const std::vector<TradeRow>& rows);

// `text` with every block regenerated; `blocks` counts them. HarnessError (naming `where` and
// the line) for a block without its end.
std::string refresh_generated(const std::string& text, const std::vector<TradeRow>& rows, const std::string& where, int* blocks);

}  // namespace harness
