// Where the expert rule puts T3 on a generated last against the farthest feather-line point from T2, the
// bound ExpertSplitOnLasts asserts (< 1.5 mm) for one last: run it over sizes, sides and triangle counts to
// see whether a surface meets it as a rule or by chance (docs/subdivision.md, "The sample last").
//   build/bin/expert_heel_point EU left|right TRIANGLES [legacy]   (Bezier surface unless "legacy")
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/segment/expert_split_plane.hpp"
#include "engine/segment/segment_last.hpp"

int main(int argc, char** argv) {
  using namespace lastcut;
  int eu = 0, triangles = 0;
  std::string side_name, legacy;
  CLI::App app{"Where the expert rule puts T3 on a generated last against the farthest feather-line point from T2 "
               "(bound 1.5 mm, ExpertSplitOnLasts)"};
  app.add_option("EU", eu, "EU size of the last")->required()->check(CLI::Range(35, 47));
  app.add_option("side", side_name, "foot side: left or right")->required()->check(CLI::IsMember({"left", "right"}));
  app.add_option("TRIANGLES", triangles, "target triangle count of the last")
      ->required()
      ->check(CLI::Range(2000, 2'000'000));
  app.add_option("legacy", legacy, "\"legacy\": the remeshed surface instead of the Bezier one")
      ->check(CLI::IsMember({"legacy"}));
  CLI11_PARSE(app, argc, argv);
  const FootSide side = side_name == "left" ? FootSide::Left : FootSide::Right;
  LastParams params = LastParams::for_eu_size(eu, side);
  params.target_triangles = triangles;
  params.surface = legacy == "legacy" ? LastSurface::Remeshed : LastSurface::Bezier;
  // Generated lasts are in the canonical frame already: no orientation step (as in the test).
  const OrientedLast last{generate_last(params).mesh, Eigen::Affine3d::Identity(), side, {}};
  SegmentOptions options;
  options.split_rule = SplitRule::Expert;
  const BandCut band = cut_band(last, options);
  const SplitPlane plane = place_split_plane(band, options);
  const std::vector<Eigen::Vector3d>& lower = band.lower_loop;
  double x_back = INFINITY;
  for (const Eigen::Vector3d& p : lower) x_back = std::min(x_back, p.x());
  // The feather line sampled every ~0.02 mm, as the test does.
  std::vector<Eigen::Vector3d> fine;
  for (size_t i = 0; i < lower.size(); ++i)
    for (int s = 0; s < 100; ++s) fine.push_back(lower[i] + (lower[(i + 1) % lower.size()] - lower[i]) * (s / 100.0));
  size_t far = 0;
  for (size_t i = 0; i < fine.size(); ++i)
    if ((fine[i] - plane.T2).norm() > (fine[far] - plane.T2).norm()) far = i;
  std::printf("EU %d %s, %d triangles, %s: T3 %.2f mm from the farthest point (bound 1.5), %.2f mm ahead of the back-most (bound 0.5)\n",
              eu, side_name.c_str(), params.target_triangles, params.surface == LastSurface::Bezier ? "Bezier" : "legacy",
              (plane.T3 - fine[far]).norm(), plane.T3.x() - x_back);
  return 0;
}
