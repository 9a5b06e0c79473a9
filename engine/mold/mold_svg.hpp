#pragma once
// A picture of a mold for people: the flattened triangles coloured by how much the leather has to
// stretch there (a heat map with a legend), the cutting outline, the net line inside the allowance
// (dashed), the notches and a 50 mm scale bar.
// The SVG is sized in millimetres, so printed at 100 % it is the mold at 1:1. Y points up as in
// the DXF (the picture is not mirrored).
#include <Eigen/Core>
#include <filesystem>

#include "engine/mold/mold.hpp"

namespace lastcut {

// UV #V x 2 (mm), F #F x 3, stretch_per_triangle #F (1 = unstrained; typically the larger
// singular value of each triangle's 3D->2D map). Throws EngineError on size mismatch or when the
// file cannot be written.
void write_mold_svg(const std::filesystem::path& path, const Mold& mold, const Eigen::MatrixXd& UV,
                    const Eigen::MatrixXi& F, const Eigen::VectorXd& stretch_per_triangle);

}  // namespace lastcut
