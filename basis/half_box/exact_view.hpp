#pragma once
// The scheme-neutral subdivision view (basis/subdivision_view.hpp) of half-box EF patches: cubic Bézier
// triangles (the 13 regular blending functions) on the three tiles of a layer, A the patch subdivision matrix.
#include "basis/subdivision_view.hpp"

namespace iga::basis::half_box {

/// The view of valence n (subdivision_structure(n)): A = patch_matrix, w = limit_stencil, tile k's points
/// X^k Ā (13 × (n+7)) with its tile map's jacobian. Cached per valence, thread-safe; UnsupportedError for
/// valences without a structure.
const SubdivisionView& half_box_view(int n);

}  // namespace iga::basis::half_box
