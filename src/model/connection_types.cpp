#include "src/model/connection_types.hpp"

#include <array>
#include <cctype>
#include <vector>

#include "base/suggest.hpp"

namespace clinch {
namespace {

constexpr ComponentMask bits(std::initializer_list<int> components) {
  ComponentMask mask = 0;
  for (int c : components) mask = static_cast<ComponentMask>(mask | (1u << (c - 1)));
  return mask;
}

constexpr ConnectionKind T = ConnectionKind::Translational;
constexpr ConnectionKind R = ConnectionKind::Rotational;
constexpr ConnectionKind A = ConnectionKind::Assembled;
constexpr OrientationUse ign = OrientationUse::Ignored;
constexpr OrientationUse opt = OrientationUse::Optional;
constexpr OrientationUse req = OrientationUse::Required;
constexpr V1Support yes = V1Support::Supported;
constexpr V1Support no = V1Support::Unsupported;

// connection-types.md §2.1, row by row. The CONN2D2 columns follow the "In two dimensions"
// paragraph: the 3-D masks restricted to components 1, 2, 6 for the nine types allowed there.
// CONSTANT VELOCITY and CVJOINT components are "not confirmed" (§6 item 7); v1 rejects both.
constexpr ConnectionTypeInfo kTypes[] = {
    // name, kind, available, constrained, ori a, ori b, 3-D only, v1, 2-D allowed, 2-D masks
    {"AXIAL", T, bits({1}), 0, opt, opt, false, yes, true, bits({1}), 0},
    {"CARTESIAN", T, bits({1, 2, 3}), 0, opt, ign, false, yes, true, bits({1, 2}), 0},
    {"JOIN", T, 0, bits({1, 2, 3}), opt, ign, false, yes, true, 0, bits({1, 2})},
    {"LINK", T, 0, bits({1}), ign, ign, false, yes, true, 0, bits({1})},
    {"SLOT", T, bits({1}), bits({2, 3}), req, ign, false, yes, true, bits({1}), bits({2})},
    {"SLIDE-PLANE", T, bits({2, 3}), bits({1}), req, ign, true, yes, false, 0, 0},
    {"RADIAL-THRUST", T, bits({1, 3}), 0, req, ign, true, yes, false, 0, 0},
    {"PROJECTION CARTESIAN", T, bits({1, 2, 3}), 0, req, opt, true, yes, false, 0, 0},
    {"ACCELEROMETER", T, bits({1, 2, 3}), 0, opt, ign, false, V1Support::Converted, true,
     bits({1, 2}), 0},
    {"ALIGN", R, 0, bits({4, 5, 6}), opt, opt, false, yes, true, 0, bits({6})},
    {"CARDAN", R, bits({4, 5, 6}), 0, opt, opt, true, yes, false, 0, 0},
    {"EULER", R, bits({4, 5, 6}), 0, opt, opt, true, yes, false, 0, 0},
    {"ROTATION", R, bits({4, 5, 6}), 0, opt, opt, false, yes, true, bits({6}), 0},
    {"REVOLUTE", R, bits({4}), bits({5, 6}), req, opt, true, yes, false, 0, 0},
    {"UNIVERSAL", R, bits({4, 6}), bits({5}), req, opt, true, yes, false, 0, 0},
    {"FLEXION-TORSION", R, bits({4, 5, 6}), 0, req, opt, true, yes, false, 0, 0},
    {"PROJECTION FLEXION-TORSION", R, bits({4, 5, 6}), 0, req, opt, true, yes, false, 0, 0},
    {"CONSTANT VELOCITY", R, bits({4, 5}), bits({6}), req, opt, true, no, false, 0, 0},
    {"ROTATION ACCELEROMETER", R, 0, 0, opt, opt, true, no, false, 0, 0},
    {"FLOW-CONVERTER", R, 0, 0, ign, ign, true, no, false, 0, 0},
    {"BEAM", A, 0, bits({1, 2, 3, 4, 5, 6}), opt, opt, false, yes, true, 0, bits({1, 2, 6})},
    {"WELD", A, 0, bits({1, 2, 3, 4, 5, 6}), opt, opt, false, yes, true, 0, bits({1, 2, 6})},
    {"BUSHING", A, bits({1, 2, 3, 4, 5, 6}), 0, req, opt, true, yes, false, 0, 0},
    {"CYLINDRICAL", A, bits({1, 4}), bits({2, 3, 5, 6}), req, opt, true, yes, false, 0, 0},
    {"HINGE", A, bits({4}), bits({1, 2, 3, 5, 6}), req, opt, true, yes, false, 0, 0},
    {"PLANAR", A, bits({2, 3, 4}), bits({1, 5, 6}), req, opt, true, yes, false, 0, 0},
    {"TRANSLATOR", A, bits({1}), bits({2, 3, 4, 5, 6}), req, opt, true, yes, false, 0, 0},
    {"UJOINT", A, bits({4, 6}), bits({1, 2, 3, 5}), req, opt, true, yes, false, 0, 0},
    {"CVJOINT", A, bits({4, 5}), bits({1, 2, 3, 6}), req, opt, true, no, false, 0, 0},
    {"RETRACTOR", A, 0, 0, ign, ign, true, no, false, 0, 0},
    {"SLIPRING", A, 0, 0, ign, ign, true, no, false, 0, 0},
};

OrientationUse stronger(OrientationUse a, OrientationUse b) {
  return static_cast<std::uint8_t>(a) >= static_cast<std::uint8_t>(b) ? a : b;
}

}  // namespace

std::span<const ConnectionTypeInfo> connection_types() { return kTypes; }

std::string connection_type_key(std::string_view spelled) {
  std::string key;
  key.reserve(spelled.size());
  for (char c : spelled) {
    if (c == ' ' || c == '\t' || c == '-' || c == '_') continue;
    key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return key;
}

namespace {

// connection_type_key(a) == connection_type_key(b), without building either key: a deck names a
// type once per section, and a check of many sections looks each one up several times.
bool same_key(std::string_view a, std::string_view b) {
  auto separator = [](char c) { return c == ' ' || c == '\t' || c == '-' || c == '_'; };
  std::size_t i = 0, j = 0;
  for (;;) {
    while (i < a.size() && separator(a[i])) ++i;
    while (j < b.size() && separator(b[j])) ++j;
    if (i == a.size() || j == b.size()) return i == a.size() && j == b.size();
    if (std::toupper(static_cast<unsigned char>(a[i])) !=
        std::toupper(static_cast<unsigned char>(b[j]))) {
      return false;
    }
    ++i;
    ++j;
  }
}

}  // namespace

const ConnectionTypeInfo* find_connection_type(std::string_view spelled) {
  for (const ConnectionTypeInfo& info : kTypes) {
    if (same_key(info.name, spelled)) return &info;
  }
  return nullptr;
}

const ConnectionTypeInfo& converted_type() { return kTypes[1]; }

std::optional<std::string> suggest_connection_type(std::string_view spelled) {
  std::vector<std::string> keys;
  keys.reserve(std::size(kTypes));
  for (const ConnectionTypeInfo& info : kTypes) keys.push_back(connection_type_key(info.name));
  auto guess = closest_match(connection_type_key(spelled), keys);
  if (!guess) return std::nullopt;
  for (const ConnectionTypeInfo& info : kTypes) {
    if (connection_type_key(info.name) == *guess) return std::string(info.name);
  }
  return std::nullopt;
}

ConnectionSummary summarize_connection(std::span<const ConnectionTypeInfo* const> types,
                                       bool two_d) {
  ConnectionSummary summary;
  for (const ConnectionTypeInfo* info : types) {
    if (!info) continue;
    if (two_d) {
      summary.available |= info->available_2d;
      summary.constrained |= info->constrained_2d;
    } else {
      summary.available |= info->available;
      summary.constrained |= info->constrained;
    }
    summary.orientation_a = stronger(summary.orientation_a, info->orientation_a);
    summary.orientation_b = stronger(summary.orientation_b, info->orientation_b);
    summary.three_d_only = summary.three_d_only || info->three_d_only;
  }
  return summary;
}

std::string component_list(ComponentMask mask) {
  std::string text;
  for (int c = 1; c <= 6; ++c) {
    if (!has_component(mask, c)) continue;
    if (!text.empty()) text += ", ";
    text += static_cast<char>('0' + c);
  }
  return text.empty() ? "none" : text;
}

std::string connection_display(const ConnectorSection& section) {
  std::string text;
  for (const std::string& name : section.type_names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

}  // namespace clinch
