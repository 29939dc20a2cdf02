#include "src/model/name.hpp"

#include <cctype>

namespace clinch {

std::string name_key(const std::string& text, bool quoted) {
  if (quoted) return text;
  std::string key = text;
  for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return key;
}

}  // namespace clinch
