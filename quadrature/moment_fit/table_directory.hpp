#pragma once
// Where the fitted rules' tables (cc_<space>_n<N>.txt) are found when no directory is given: next to the
// library itself, so an installed (and moved) prefix finds its own share/iga/quadrature, and the build tree
// finds the repository's data/quadrature through a marker file that only the build tree has.
#include <string>

#include "quadrature/moment_fit/fit.hpp"

namespace iga::quadrature::moment_fit {

/// The directory of the tables of `space`, looked up in this order:
///   1. $IGA_QUADRATURE_DIR when it is set (used as given, like fitted:DIR: no fallback past an explicit choice);
///   2. <dir of libiga_quadrature>/<libdir-to-datadir>/iga/quadrature, the install layout (../share/iga/quadrature
///      for the default GNUInstallDirs; the library is located with dladdr, so a moved prefix still works);
///   3. the directory named in <dir of libiga_quadrature>/iga-build-tree-quadrature-dir.txt, a file that only the
///      build tree holds (the source tree's data/quadrature); an installed library never names a source path.
/// 2 and 3 count only when the directory holds at least one table of `space`. InputError naming every place
/// looked at (and why each failed) when none does.
std::string default_table_directory(Space space);

}  // namespace iga::quadrature::moment_fit
