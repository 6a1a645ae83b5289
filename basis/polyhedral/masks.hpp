#pragma once
// The masks of every configuration, degree-raised to bi-3: the one place that knows which derivation serves
// which configuration (regular: bezier.hpp closed form; star: star_cap.hpp; n-gon: ngon_cap.hpp; polar:
// polar_cap.hpp; T0, T1, T2: tjunction_cap.hpp).
#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// Whether a mask is available for the configuration and valence.
bool has_mask(Configuration c, int valence);

/// The configuration's mask with its patches in the degrees the paper outputs (regular: (2,2); polar: (3,2);
/// others (3,3)); cached, thread-safe. UnsupportedError naming the configuration and valence when no mask is
/// available or its derivation failed (with the reason).
const ConfigurationMask& native_mask(Configuration c, int valence);

/// The same with every patch raised to degree (3, 3).
const ConfigurationMask& bicubic_mask(Configuration c, int valence);

}  // namespace iga::basis::polyhedral
