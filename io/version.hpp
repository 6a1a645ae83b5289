#pragma once
// The version of this build: project(iga VERSION ...) in CMakeLists.txt, and the git revision it was built from
// (cmake/version.cmake regenerates both before every build).

namespace iga::io {

/// "MAJOR.MINOR.PATCH", as in CMakeLists.txt's project().
const char* version();
/// The abbreviated commit the library was built from, with "-dirty" when tracked files had changes, or
/// "unknown" when built outside a git checkout.
const char* git_revision();
/// The version of the layout of the JSON reports of the iga-* programs (README, "Reports"); raised when a key
/// changes meaning or disappears.
inline constexpr int kReportSchemaVersion = 1;

}  // namespace iga::io
