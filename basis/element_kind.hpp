#pragma once
// What a quadrature provider dispatches on: the shape of an element's reference domain and the family of
// functions that live on it.
#include <string>

namespace iga::basis {

/// Reference domain of an element: the unit square [0,1]^2 or the unit triangle {u, v >= 0, u + v <= 1}.
enum class Shape { Quad, Triangle };

/// Regular: polynomial on the element. Irregular: infinitely piecewise near an extraordinary vertex or face
/// (valence set). Polar, TJunction: the polyhedral and hierarchical configurations.
enum class Family { Regular, Irregular, Polar, TJunction };

/// The subdivision scheme an Irregular element belongs to, so that a rule made for one scheme (a tile layout,
/// a fitted table) is never applied to another. None for polynomial elements.
enum class Scheme { None, CatmullClark, HalfBox };

struct ElementKind {
  Shape shape = Shape::Quad;
  Family family = Family::Regular;
  int valence = 4;  ///< n of the extraordinary vertex or face when Irregular; 4 (quad) or 6 (triangle) otherwise
  bool boundary = false;  ///< Irregular: the extraordinary vertex lies on the boundary (its ring is not closed)
  Scheme scheme = Scheme::None;  ///< Irregular: the scheme whose eigenstructure evaluates the element

  friend bool operator==(const ElementKind&, const ElementKind&) = default;
};

/// A small integer code of a kind for output (the VTK cell array `element_kind`):
/// scheme * 10000 + shape * 1000 + family * 100 + valence (scheme 0 none, 1 Catmull–Clark, 2 half-box).
inline int kind_code(const ElementKind& k) {
  return static_cast<int>(k.scheme) * 10000 + static_cast<int>(k.shape) * 1000 + static_cast<int>(k.family) * 100 +
         k.valence;
}

/// "quad/regular", "quad/irregular:5 (catmull-clark)", "triangle/irregular:7 (half-box)", ...
std::string to_string(const ElementKind& k);

}  // namespace iga::basis
