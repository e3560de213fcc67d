// Checks of ExportParams against its tables (export_params.h) before any value reaches POV-Ray
// text: the scene reader already checked the same rows, this is the second line of defence.
#include "povgen/export_params.h"

#include "povgen/templates.h"

namespace raintrace::povgen {

void validate(const ExportParams& look) {
  sim::validate(look.camera);
  sim::check_params<ExportParams>(kExportParams, look);
  sim::check_params<FogParams>(kFogParams, look.fog);
  // The name goes into no text, but an unknown one would silently pick no environment.
  if (look.environment.include_path.empty()) environment_template(look.environment.name);
}

}  // namespace raintrace::povgen
