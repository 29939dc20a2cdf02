// The connection-type library as data (connection-types.md §2.1): for every type Abaqus knows,
// its kind, available and constrained components (3-D and CONN2D2), the use of orientations at
// nodes a and b, and whether clinch v1 supports it. The section reader looks names up here; the
// validator combines the types of a section (§1.5) into its component masks.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "src/model/section_model.hpp"

namespace clinch {

enum class ConnectionKind : std::uint8_t { Translational, Rotational, Assembled };

// Ori a / ori b column of the master table. "–" (types with no orientation at all) is Ignored.
enum class OrientationUse : std::uint8_t { Ignored, Optional, Required };

enum class V1Support : std::uint8_t { Supported, Converted, Unsupported };

struct ConnectionTypeInfo {
  std::string_view name;  // canonical spelling of the master table ("SLIDE-PLANE")
  ConnectionKind kind;
  ComponentMask available;  // 3-D (CONN3D2)
  ComponentMask constrained;
  OrientationUse orientation_a;
  OrientationUse orientation_b;
  bool three_d_only;
  V1Support support;
  // CONN2D2 (§2.1 "In two dimensions"): only components 1, 2, 6 exist. Meaningful only for the
  // types allowed on CONN2D2 (allowed_2d).
  bool allowed_2d;
  ComponentMask available_2d;
  ComponentMask constrained_2d;
};

// Every type of the master table, in table order.
std::span<const ConnectionTypeInfo> connection_types();

// Lookup key of a spelling: upper case, blanks, hyphens and underscores dropped, so that
// "constant_velocity", "Constant Velocity" and "CONSTANT-VELOCITY" are one name (§1.3). The
// lexer removes inner blanks from unquoted fields, so dropping separators (rather than unifying
// them) is what makes "PROJECTION CARTESIAN" work.
std::string connection_type_key(std::string_view spelled);

// The type a spelling names, or nullptr. ACCELEROMETER is returned as itself; the caller converts
// it (support == Converted, converted_type()).
const ConnectionTypeInfo* find_connection_type(std::string_view spelled);

// CARTESIAN, the type ACCELEROMETER becomes in a static step (§1.5 rule 4).
const ConnectionTypeInfo& converted_type();

// The closest known name for a did-you-mean note.
std::optional<std::string> suggest_connection_type(std::string_view spelled);

// Components 1, 2 and 6: the only ones of a CONN2D2 element.
constexpr ComponentMask kComponents2D = 0b100011;
constexpr ComponentMask kAllComponents = 0b111111;

// Result of combining the (one or two) types of a section line (§1.5 rule 1).
struct ConnectionSummary {
  ComponentMask available = 0;
  ComponentMask constrained = 0;
  OrientationUse orientation_a = OrientationUse::Ignored;
  OrientationUse orientation_b = OrientationUse::Ignored;
  bool three_d_only = false;
};

// Union of the masks; the strongest orientation use at each end (required > optional >
// ignored). `two_d` selects the CONN2D2 masks.
ConnectionSummary summarize_connection(std::span<const ConnectionTypeInfo* const> types,
                                       bool two_d);

// The section's available components (filled by resolve_sections; CONN2D2 sections hold only
// components of {1, 2, 6}).
inline ComponentMask available_components(const ConnectorSection& section) {
  return section.available;
}
inline ComponentMask constrained_components(const ConnectorSection& section) {
  return section.constrained;
}

// "1, 2, 6" (or "none") for messages.
std::string component_list(ComponentMask mask);

// Display of a section's connection for messages: "HINGE", "CARTESIAN, CARDAN".
std::string connection_display(const ConnectorSection& section);

}  // namespace clinch
