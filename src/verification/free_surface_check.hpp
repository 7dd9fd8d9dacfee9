#pragma once
// Free-surface detection on known shapes: particles on a lattice of spacing d inside a shape,
// optionally displaced by up to `disorder` d. The truth, from the lattice before displacement: a
// fluid particle is on the outer layer when one of its axial lattice neighbours is empty (neither
// fluid nor wall), interior when none of its 3^D - 1 lattice neighbours is; particles with only a
// diagonal neighbour empty (corners of a staircase boundary such as the disc's) are not scored.
// Reported: recall (outer layer flagged), precision (flagged and scored particles that are outer)
// and the number of interior particles flagged.
#include <string>
#include <vector>

namespace ryushi {

struct FreeSurfaceScore {
  std::string shape;
  std::size_t outer = 0, interior = 0, outer_flagged = 0, interior_flagged = 0;
  double recall() const { return outer ? double(outer_flagged) / outer : 1.0; }
  double precision() const {
    auto flagged = outer_flagged + interior_flagged;
    return flagged ? double(outer_flagged) / flagged : 1.0;
  }
};

const std::vector<std::string>& free_surface_shapes();  // square, disc, square_with_hole, column, cube
FreeSurfaceScore score_free_surface(const std::string& shape, const std::string& rule, double disorder,
                                    unsigned seed = 1, double spacing = 0.02, double beta = 0.85);

}  // namespace ryushi
