// The linear deflection a B-rep part is meshed at (scene/scene.h).
#include "brep/brep_file.h"
#include "scene/placement.h"
#include "scene/scene.h"
#include "scene/units.h"
#include "tolerances.h"

namespace pd {

double brep_deflection(const SceneSpec& s, const PartSpec& p) {
  if (p.deflection) return *p.deflection;
  if (s.deflection) return *s.deflection;
  if (!s.auto_tolerance && s.tolerance && *s.tolerance > 0)
    return tol::kDeflectionFraction * *s.tolerance;
  const std::optional<double> scene_mm = unit_in_mm(s.units.value_or("mm"));
  return tol::kAutoDeflectionMm / scene_mm.value_or(1.0);
}

double file_deflection(const SceneSpec& scene, const PartSpec& spec) {
  if (!spec.mesh || !is_brep_path(*spec.mesh)) return 0.0;
  return brep_deflection(scene, spec) / stretch(placement(spec));
}

}  // namespace pd
