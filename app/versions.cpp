#include "app/versions.h"

#include <CGAL/version.h>
#include <tbb/version.h>
#include <vtkVersion.h>

#include <Eigen/Core>
#include <string>

#include "solver/patches/ceres/ceres_patch.h"
#include "solver/sqp/blas_threads.h"
#include "solver/sqp/cholmod_factor.h"

namespace sdog::cli {

nlohmann::json software_versions() {
  auto dotted = [](int a, int b, int c) {
    return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c);
  };
  return {{"sdog", SDOG_VERSION},
          {"sdog_commit", SDOG_GIT_COMMIT},
          {"compiler", __VERSION__},
          {"eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
          {"cgal", CGAL_VERSION_STR},
          {"ceres", ceres_version()},
          {"cholmod", cholmod_version()},
          {"blas", blas_description()},
          {"tbb", TBB_VERSION_STRING},
          {"vtk", vtkVersion::GetVTKVersion()},
          {"nlohmann_json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                                   NLOHMANN_JSON_VERSION_PATCH)}};
}

std::string version_line(const std::string& program) {
  return program + " " + SDOG_VERSION + " (commit " + SDOG_GIT_COMMIT + ")";
}

}  // namespace sdog::cli
