// What brep_file.h declares that needs no Open CASCADE call: a B-rep file's
// name, the sag's basis, and the version B-rep meshes depend on. These run in
// every process, also those that never load the Open CASCADE module
// (brep/brep_backend.h).
#include <Standard_Version.hxx>  // a macro only: no Open CASCADE library is linked for it
#include <algorithm>
#include <cctype>

#include "brep/brep_file.h"

namespace pd {

bool is_brep_path(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == "step" || ext == "stp" || ext == "brep";
}

std::string brep_mesh_version() {
  return std::string("pdcheck-brep-v2 occt-") + OCC_VERSION_COMPLETE;
}

const char* sag_basis_name(SagBasis b) {
  return b == SagBasis::kBound ? "bound" : "estimate";
}

Tessellation combine(const Tessellation& a, const Tessellation& b) {
  Tessellation out = a;
  out.deflection = std::max(a.deflection, b.deflection);
  out.sag = std::max(a.sag, b.sag);
  out.basis = a.basis == SagBasis::kBound && b.basis == SagBasis::kBound ? SagBasis::kBound
                                                                         : SagBasis::kEstimate;
  out.faces = a.faces + b.faces;
  out.free_form = a.free_form + b.free_form;
  out.tolerance = std::max(a.tolerance, b.tolerance);
  return out;
}

}  // namespace pd
