// libFuzzer target: any byte string as a deck. A crash, a sanitizer report or a hang is a bug;
// diagnostics are the expected outcome (ARCHITECTURE.md, testing habit 6).
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  clinch::SourceManager sources;
  clinch::DiagnosticSink sink;
  clinch::Model model;
  clinch::read_deck_text("fuzz.inp", std::string(reinterpret_cast<const char*>(data), size),
                         sources, model, sink);
  for (const clinch::Diagnostic& d : sink.diagnostics()) (void)clinch::render_text(d, sources);
  return 0;
}
