// libFuzzer target: any byte string as a *PARAMETER block (one definition per line) evaluated
// by the expression language of input-syntax.md §6.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "parser/parameters.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  clinch::ParameterTable table;
  std::uint32_t line = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    table.add_line({std::string(text.substr(start, end - start)), {0, ++line, 1}});
    start = end + 1;
  }
  clinch::DiagnosticSink sink;
  table.evaluate(sink);
  (void)table.use("a");
  table.report_unused(sink);
  return 0;
}
