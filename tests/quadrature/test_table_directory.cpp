// Where --quadrature fitted finds its tables without fitted:DIR (quadrature/moment_fit/table_directory.hpp), seen
// from the build tree: $IGA_QUADRATURE_DIR first and as given; otherwise the repository's data/quadrature,
// through the marker file next to the build tree's libiga_quadrature.so. (The installed and moved library is
// checked by external_consumer, tests/consumer/run.cmake.)
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "basis/element_kind.hpp"
#include "core/error.hpp"
#include "quadrature/moment_fit/table_directory.hpp"
#include "quadrature/rule_provider.hpp"

namespace fs = std::filesystem;
using iga::quadrature::moment_fit::default_table_directory;
using iga::quadrature::moment_fit::Space;

TEST(TableDirectory, BuildTreeFindsTheRepositoryTables) {
  ::unsetenv("IGA_QUADRATURE_DIR");
  const fs::path tables = fs::path(IGA_SOURCE_DIR) / "data" / "quadrature";
  for (const Space space : {Space::Phi, Space::Mass, Space::Stiffness}) {
    EXPECT_TRUE(fs::equivalent(default_table_directory(space), tables)) << default_table_directory(space);
  }
}

TEST(TableDirectory, EnvironmentComesFirstAndIsUsedAsGiven) {
  const fs::path dir = fs::temp_directory_path() / "iga_test_table_directory" / "empty";
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(dir)) fs::remove(entry.path());
  ::setenv("IGA_QUADRATURE_DIR", dir.c_str(), 1);
  EXPECT_EQ(default_table_directory(Space::Phi), dir.string());  // no tables there: still the user's choice
  // The provider reads that folder: a valence without a table is an error naming the folder, not the
  // repository's tables in its place.
  const auto fitted = iga::quadrature::make_rule_provider("fitted", 4);
  iga::basis::ElementKind kind;
  kind.family = iga::basis::Family::Irregular;
  kind.scheme = iga::basis::Scheme::CatmullClark;
  kind.valence = 3;
  try {
    fitted->rule(kind);
    ADD_FAILURE() << "no error for an empty $IGA_QUADRATURE_DIR";
  } catch (const iga::UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
  ::unsetenv("IGA_QUADRATURE_DIR");
}
