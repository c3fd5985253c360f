#pragma once
// Meshing failures a user can cause: a degenerate primitive, a part outside the domain, a part
// completely overridden by later parts, a size field that would need an absurd mesh, a mesh
// that CGAL cannot build. The case reader maps part() (and field(), when set) back to the file
// and line of the offending entry; the CLI treats it like an InputError (exit code 2).
#include <stdexcept>
#include <string>
#include <utility>

namespace magfem {

struct MeshError : std::runtime_error {
  // part: Part2D::name, empty when the error concerns no single part (options, outer boundary).
  // field: the offending field of that part or of the options ("radius", "r_inner",
  // "vertices", "max_size", "default_size", ...), empty when no single field is at fault.
  MeshError(std::string part_name, std::string field_name, const std::string& message)
      : std::runtime_error(prefix(part_name, field_name) + message), part(std::move(part_name)),
        field(std::move(field_name)), reason(message) {}

  std::string part;
  std::string field;
  std::string reason; // the message without the part/field prefix

private:
  static std::string prefix(const std::string& part_name, const std::string& field_name) {
    std::string p;
    if (!part_name.empty())
      p += "part '" + part_name + "'";
    if (!field_name.empty())
      p += (p.empty() ? "" : ", ") + std::string("field '") + field_name + "'";
    return p.empty() ? p : p + ": ";
  }
};

} // namespace magfem
