#pragma once
// A part wholly beyond a symmetry plane is not meshed, so its region summary is empty; by
// symmetry its field is the mirror of its image's (in the model's share), so its energy,
// size and peak |B| are the image's. Filled in after the scaling to the whole device, the
// regions then sum to the whole device's energy as they do in a full model.
#include <cstddef>
#include <vector>

namespace magfem {

// regions: RegionSummary2D or RegionSummary3D, the first images.size() being the parts in
// order; images: per part, the part in the share standing for it or -1 (share_images_2d,
// share_images). Copies the image's summary into the part's, keeping the part's name and
// index, and records the image's name in from_image.
template <class Region>
void fill_mirror_image_regions(std::vector<Region>& regions, const std::vector<int>& images) {
  for (std::size_t i = 0; i < images.size() && i < regions.size(); ++i) {
    if (images[i] < 0)
      continue;
    Region r = regions[std::size_t(images[i])];
    r.from_image = r.name;
    r.name = regions[i].name;
    r.part = regions[i].part;
    regions[i] = r;
  }
}

} // namespace magfem
