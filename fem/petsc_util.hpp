#pragma once
// What the PETSc-side files of fem/ share (fem/petsc_system.cpp, fem/petsc_multigrid.cpp): a PETSc error code as
// one exception line, and owning handles of PETSc objects. Internal: only files that compile against PETSc.
#include <petscksp.h>

#include <string>

#include "core/error.hpp"

namespace iga::fem::petsc {

// PETSc's message for an error code: the specific one of the last error ("Unknown PC type: ..."), else the
// generic one, on one line.
inline std::string petsc_message(PetscErrorCode code) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  std::string m = specific && *specific ? specific : text ? text : "error " + std::to_string(code);
  for (char& c : m) {
    if (c == '\n') c = ' ';
  }
  while (!m.empty() && m.back() == ' ') m.pop_back();
  return m;
}

// A PETSc call's error code as one line.
inline void check(PetscErrorCode code, const char* what) {
  if (code != 0) throw NumericalError(std::string("PETSc: ") + what + " failed: " + petsc_message(code));
}

// Owns a PETSc object and destroys it (PETSc's XDestroy(&x) convention).
template <class T, PetscErrorCode (*Destroy)(T*)>
class Handle {
 public:
  Handle() = default;
  ~Handle() {
    if (p_) Destroy(&p_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  T* out() { return &p_; }
  void reset() {
    if (p_) Destroy(&p_);
  }
  operator T() const { return p_; }

 private:
  T p_ = nullptr;
};
using MatH = Handle<Mat, MatDestroy>;
using VecH = Handle<Vec, VecDestroy>;
using IsH = Handle<IS, ISDestroy>;
using KspH = Handle<KSP, KSPDestroy>;
using ScatterH = Handle<VecScatter, VecScatterDestroy>;

}  // namespace iga::fem::petsc
