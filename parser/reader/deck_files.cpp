#include "parser/reader/deck_files.hpp"

#include <fmt/format.h>

#include <filesystem>

namespace clinch {
namespace {

std::string resolve_path(const SourceManager& sources, std::uint32_t from_file,
                         const std::string& name) {
  std::filesystem::path p(name);
  if (p.is_absolute()) return name;
  std::string dir = sources.directory_of(from_file);
  return dir.empty() ? name : (std::filesystem::path(dir) / p).string();
}

std::string canonical(const std::string& path) {
  std::error_code ec;
  auto c = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : c.string();
}

std::string display_of_file_param(const Field& f) { return f.text; }

}  // namespace

void DeckFiles::add_main(std::uint32_t main_file) {
  loaded_.emplace(canonical(sources_.file(main_file).path), main_file);
}

std::string DeckFiles::resolve(std::uint32_t from_file, const std::string& name) const {
  return resolve_path(sources_, from_file, name);
}

std::optional<std::uint32_t> DeckFiles::load_once(const std::string& path, SourceLoc at,
                                                  std::string* error) {
  std::string key = canonical(path);
  auto it = loaded_.find(key);
  if (it != loaded_.end()) return it->second;
  auto idx = sources_.load(path, at, error);
  if (idx) loaded_.emplace(key, *idx);
  return idx;
}

std::optional<std::uint32_t> DeckFiles::try_load(const std::string& path, SourceLoc at) {
  std::string error;
  return load_once(path, at, &error);
}

void DeckFiles::include(const KeywordLine& line, LineStream& stream) {
  const KeywordParam* input = nullptr;
  for (const KeywordParam& p : line.params) {
    if (p.name == "INPUT") {
      input = &p;
    } else if (p.name == "PASSWORD") {
      sink_.report(DiagCode::unsupported_option, p.loc,
                   "encrypted include files (PASSWORD) are not supported by clinch");
      return;
    } else {
      sink_
          .report(DiagCode::unknown_parameter, p.loc,
                  fmt::format("unknown parameter '{}' for *INCLUDE", p.spelled))
          .notes.push_back({{}, "valid parameters: INPUT"});
    }
  }
  if (!input) {
    sink_.report(DiagCode::missing_parameter, line.loc, "*INCLUDE requires parameter 'INPUT'");
    return;
  }
  if (!input->has_value || input->value.text.empty()) {
    sink_.report(DiagCode::parameter_needs_value, input->loc,
                 "parameter 'INPUT' needs a value (INPUT=file)");
    return;
  }
  std::uint32_t from = stream.scanner().loc().file;
  std::string path = resolve(from, input->value.text);
  std::string key = canonical(path);
  // Cycle: the file is already open on the stack.
  for (std::size_t level = 0; level < stream.depth(); ++level) {
    if (canonical(sources_.file(stream.file_at(level)).path) == key) {
      std::string chain;
      for (std::size_t k = level; k < stream.depth(); ++k) {
        chain += sources_.file(stream.file_at(k)).display_name + " → ";
      }
      chain += input->value.text;
      sink_.report(DiagCode::include_cycle, input->value.loc,
                   fmt::format("'{}' includes itself ({})", input->value.text, chain));
      return;
    }
  }
  if (stream.depth() >= kMaxIncludeDepth) {
    sink_.report(DiagCode::include_cycle, input->value.loc,
                 fmt::format("*INCLUDE nesting deeper than {} levels", kMaxIncludeDepth));
    return;
  }
  std::string error;
  auto idx = load_once(path, input->value.loc, &error);
  if (!idx) {
    sink_.report(DiagCode::file_not_found, input->value.loc,
                 fmt::format("cannot open '{}': {}", display_of_file_param(input->value), error));
    return;
  }
  stream.push(*idx);
}

}  // namespace clinch
