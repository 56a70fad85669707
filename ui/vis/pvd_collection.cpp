#include "ui/vis/pvd_collection.h"

namespace sdog::vis {

std::string pvd_collection(const TimeSteps& steps) {
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
      "byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [step, name] : steps)
    pvd += "    <DataSet timestep=\"" + std::to_string(step) + "\" group=\"\" part=\"0\" file=\"" +
           name + "\"/>\n";
  pvd += "  </Collection>\n</VTKFile>\n";
  return pvd;
}

}  // namespace sdog::vis
