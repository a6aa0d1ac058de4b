#include "openfoam/foam/control_dict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/io/files.hpp"
#include "openfoam/foam/foam_file_header.hpp"

namespace openfoam {

namespace {

// OpenFOAM's function objects run after each step while the time is within
// half a step of [timeStart, timeEnd].
std::string object_writer(const char* name, const char* object, double first, double last) {
  return fmt::format(
      "    {0}\n    {{\n        type writeObjects;\n"
      "        libs (\"libutilityFunctionObjects.so\");\n        objects ({1});\n"
      "        writeControl timeStep;\n        writeInterval 1;\n"
      "        timeStart {2:.17g};\n        timeEnd {3:.17g};\n    }}\n",
      name, object, first, last);
}

std::string function_objects(const ControlSettings& s) {
  if (!s.write_density_at && !s.write_steps_between) return {};
  std::string text = "\nfunctions\n{\n";
  if (s.write_density_at)
    text +=
        object_writer("densityBeforeWindowEnd", "rho", *s.write_density_at, *s.write_density_at);
  if (s.write_steps_between) {
    text += object_writer("exchangeWithinWindow", "p \"kinematicCloud:UTrans\"",
                          s.write_steps_between->first, s.write_steps_between->second);
  }
  return text + "}\n";
}

}  // namespace

// startFrom latestTime with a fixed deltaT keeps the window ends exact;
// runTimeModifiable off spares the solver polling its dictionaries. The
// Courant limits are read by the VOF solvers even with a fixed step.
std::string control_dict(const ControlSettings& s) {
  return foam_file_header({"dictionary", "system", "controlDict"}) +
         fmt::format(
             "application {};\n"
             "startFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime {:.17g};\n"
             "deltaT {:.17g};\n"
             "writeControl timeStep;\nwriteInterval {};\npurgeWrite 0;\n"
             "writeFormat ascii;\nwritePrecision 12;\nwriteCompression off;\n"
             "timeFormat general;\ntimePrecision {};\n"
             "runTimeModifiable false;\nadjustTimeStep no;\nmaxCo 1;\nmaxAlphaCo 1;\n"
             "maxDeltaT 1;\n",
             s.application, s.end_time, s.time_step, s.write_every, time_precision) +
         function_objects(s);
}

void write_control_dict(const std::filesystem::path& case_dir, const ControlSettings& settings) {
  cosim::write_file_atomically(case_dir / "system" / "controlDict", control_dict(settings));
}

bool is_whole_number_of_steps(double interval, double step) {
  const double n = interval / step;
  return std::abs(n - std::round(n)) <= 1e-9 * std::max(1.0, n);
}

}  // namespace openfoam
