#pragma once
// Inside the PETSc module: a PETSc call's error code becomes SolveError, with PETSc's own
// message for it ("PETSc: <what> failed: <message>"). Defined in petsc_ksp_solver.cpp, whose
// error handler records the message.
#include <petscsys.h>

namespace magfem::petsc_module {

void check(PetscErrorCode code, const char* what);

} // namespace magfem::petsc_module
