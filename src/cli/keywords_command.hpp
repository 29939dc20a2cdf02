// `clinch keywords [NAME] [--format text|markdown]`: what the deck language supports, read from
// the keyword registry (parameters and their allowed values, where a keyword may stand, how its
// data lines are read, what is refused) with the prose of src/cli/keyword_notes.cpp. An
// extension of the command-line contract (docs/cli-contract.md): exit 0 printed, 1 NAME is not a
// keyword clinch knows, 3 usage or I/O. docs/keywords.md is the markdown form.
#pragma once

#include <optional>
#include <string>

namespace clinch {

enum class KeywordsFormat { Text, Markdown };

struct KeywordsOptions {
  std::optional<std::string> name;  // one keyword (with or without '*', any case); all if absent
  KeywordsFormat format = KeywordsFormat::Text;
};

int run_keywords(const KeywordsOptions& options);

}  // namespace clinch
