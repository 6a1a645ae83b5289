// Sides of the reference elements (basis/space.hpp): side k runs counter-clockwise from corner k to corner
// k + 1 with the stated tangent, for the unit square and the unit triangle.
#include <gtest/gtest.h>

#include "basis/space.hpp"
#include "core/error.hpp"

using namespace iga::basis;

TEST(ReferenceElement, SidesRunFromCornerToCorner) {
  const std::vector<Eigen::Vector2d> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Eigen::Vector2d> triangle = {{0, 0}, {1, 0}, {0, 1}};
  for (const auto& [shape, corners] : {std::pair{Shape::Quad, square}, std::pair{Shape::Triangle, triangle}}) {
    const int n = num_sides(shape);
    ASSERT_EQ(n, static_cast<int>(corners.size()));
    double signed_area = 0.0;
    for (int s = 0; s < n; ++s) {
      const Eigen::Vector2d a = corners[static_cast<std::size_t>(s)], b = corners[static_cast<std::size_t>((s + 1) % n)];
      EXPECT_EQ(side_point(shape, s, 0.0), a) << s;
      EXPECT_EQ(side_point(shape, s, 1.0), b) << s;
      EXPECT_EQ(side_tangent(shape, s), b - a) << s;
      EXPECT_EQ(side_point(shape, s, 0.25), a + 0.25 * (b - a)) << s;
      signed_area += 0.5 * (a.x() * b.y() - b.x() * a.y());
    }
    EXPECT_DOUBLE_EQ(signed_area, shape == Shape::Quad ? 1.0 : 0.5);  // counter-clockwise
    EXPECT_THROW(side_point(shape, n, 0.5), iga::InputError);
    EXPECT_THROW(side_tangent(shape, -1), iga::InputError);
  }
}
