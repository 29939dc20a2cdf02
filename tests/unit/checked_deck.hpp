// Test support: a deck read through the whole reader (with validation), kept together with its
// sources and diagnostics, and queries on the diagnostics that the keyword-family tests share.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/diagnostic.hpp"
#include "parser/deck_reader.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

struct CheckedDeck {
  SourceManager sources;
  Model model;
  DiagnosticSink sink;

  // Every diagnostic with this code, in report order.
  std::vector<const Diagnostic*> with(DiagCode code) const {
    std::vector<const Diagnostic*> out;
    for (const Diagnostic& d : sink.diagnostics()) {
      if (d.code == code) out.push_back(&d);
    }
    return out;
  }
  const Diagnostic* first(DiagCode code) const {
    auto all = with(code);
    return all.empty() ? nullptr : all.front();
  }
  // The one diagnostic of `code`; fails the test if there is not exactly one.
  const Diagnostic& one(DiagCode code) const {
    static const Diagnostic kNone{};
    auto found = with(code);
    EXPECT_EQ(found.size(), 1u) << "code " << diag_code_id(code) << ":\n" << dump();
    return found.empty() ? kNone : *found.front();
  }
  // Every diagnostic as "name line:column message", for failure messages.
  std::string dump() const {
    std::string out;
    for (const Diagnostic& d : sink.diagnostics()) {
      out += std::string(diag_code_name(d.code)) + " " + std::to_string(d.loc.line) + ":" +
             std::to_string(d.loc.column) + " " + d.message + "\n";
    }
    return out;
  }
};

// `text` read as the deck "deck.inp" through the whole reader (resolve and checks included).
inline std::unique_ptr<CheckedDeck> read_checked_deck(const std::string& text) {
  auto deck = std::make_unique<CheckedDeck>();
  read_deck_text("deck.inp", text, deck->sources, deck->model, deck->sink);
  return deck;
}

}  // namespace clinch
