#pragma once
// Where the region-by-region recoveries (RecoveredB3D, PatchRecovery2D, PatchRecovery3D) keep
// their values: one slot per (DOF, region) pair, a region being an element part. A DOF inside
// one region has one slot; a DOF on an interface one per region around it, so a region never
// reads another's field (B_t jumps by mu_r across an interface). Stored like CSR: DOF d's slots
// are begin(d) .. end(d) - 1.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace magfem {

class RegionSlots {
public:
  RegionSlots() = default; // none: empty()

  // Elements 0 .. n_elements - 1; element_dofs(e) -> const int* to its dofs_per_element DOFs,
  // part_of(e) -> its region, or skip (an element that holds no values, e.g. a shell tet).
  static constexpr int skip = std::numeric_limits<int>::min();
  template <class ElementDofs, class PartOf>
  RegionSlots(int n_dofs, std::size_t n_elements, int dofs_per_element, ElementDofs&& element_dofs,
              PartOf&& part_of) {
    // The region of the first element at each DOF, and (DOF, region) for any element of
    // another region: only interface DOFs add pairs, so this stays small next to the mesh.
    std::vector<int> first_part(static_cast<std::size_t>(n_dofs), skip);
    std::vector<std::pair<int, int>> others;
    for (std::size_t e = 0; e < n_elements; ++e) {
      const int part = part_of(e);
      if (part == skip)
        continue;
      const int* dof = element_dofs(e);
      for (int i = 0; i < dofs_per_element; ++i) {
        int& p = first_part[dof[i]];
        if (p == skip)
          p = part;
        else if (p != part)
          others.emplace_back(dof[i], part);
      }
    }
    std::sort(others.begin(), others.end());
    others.erase(std::unique(others.begin(), others.end()), others.end());
    first_.assign(first_part.size() + 1, 0);
    part_.reserve(first_part.size() + others.size());
    std::size_t k = 0;
    for (std::size_t d = 0; d < first_part.size(); ++d) {
      if (first_part[d] != skip)
        part_.push_back(first_part[d]);
      for (; k < others.size() && others[k].first == static_cast<int>(d); ++k)
        part_.push_back(others[k].second);
      first_[d + 1] = static_cast<int>(part_.size());
    }
  }

  bool empty() const { return first_.empty(); }
  int n_dofs() const { return empty() ? 0 : static_cast<int>(first_.size()) - 1; }
  std::size_t size() const { return part_.size(); } // slots
  int begin(int dof) const { return first_[dof]; }
  int end(int dof) const { return first_[dof + 1]; }
  int regions_at(int dof) const { return first_[dof + 1] - first_[dof]; }
  int part(int slot) const { return part_[slot]; }

  // -1 if region `part` does not touch `dof`.
  int slot(int dof, int part) const {
    for (int s = first_[dof]; s < first_[dof + 1]; ++s)
      if (part_[s] == part)
        return s;
    return -1;
  }
  // The slot of region `part` at `dof`, asked by an element of that region holding the DOF.
  // A DOF inside one region has one slot, the element's, returned without reading its region
  // (a cache miss per DOF: 3 % of benchmark32's run when every lookup read it).
  int own_slot(int dof, int part) const {
    return first_[dof + 1] - first_[dof] == 1 ? first_[dof] : slot(dof, part);
  }

private:
  std::vector<int> first_; // n_dofs + 1
  std::vector<int> part_;  // region of every slot
};

} // namespace magfem
