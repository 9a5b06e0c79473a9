// Reflection lines on the Bezier surface of a generated last's quad control mesh, sampled at n = 3
// and at the Catmull-Clark-like n = 4, side by side: a small software rasteriser (z-buffer,
// per-pixel interpolated exact surface normals du x dv of the patches) writes a binary PPM. The
// stripes are the reflected view vector against an environment of parallel bands; they bend smoothly
// where the surface is C2 and kink where only the position (C0) is shared. Red dots mark the
// extraordinary (valence-3) control vertices.
//   build/bin/render_reflection_lines OUT.ppm [control_quads] [view: side|toe|generated]
// `generated`: left panel the generator's Bezier last (50k triangles, sharp flat top cut, vertex
// normals averaged on the side and the cut's normal on the cap), right the closed control mesh at n = 4.
//   convert OUT.ppm docs/pictures/reflection-lines.png
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "engine/lastgen/generate_last.hpp"
#include "engine/lastgen/last_control_mesh.hpp"
#include "engine/subdiv/sample_surface.hpp"

namespace {

using namespace lastcut;

constexpr int kPanelWidth = 640, kPanelHeight = 420;

struct Camera {
  Eigen::Vector3d forward, right, up;
};

struct Image {
  int width, height;
  std::vector<unsigned char> rgb;
  std::vector<double> depth;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(3 * w * h), 255), depth(static_cast<size_t>(w * h), std::numeric_limits<double>::infinity()) {}
};

// Draws `mesh` with per-corner unit normals (corner k of face f: row 3 f + k of corner_normal) into
// the panel at x0; returns the map from model points to pixels (x, y, depth).
std::function<Eigen::Vector3d(const Eigen::Vector3d&)> rasterise(Image& image, int x0, const TriMesh& mesh, const Eigen::MatrixXd& corner_normal,
                                                                 const Camera& camera, const Eigen::Vector3d& stripe_axis) {
  const int vertices = mesh.vertex_count();
  Eigen::MatrixXd screen(vertices, 3);
  for (int v = 0; v < vertices; ++v) {
    const Eigen::Vector3d p = mesh.V.row(v).transpose();
    screen.row(v) << p.dot(camera.right), p.dot(camera.up), p.dot(camera.forward);
  }
  const Eigen::Vector3d low = screen.colwise().minCoeff(), high = screen.colwise().maxCoeff();
  const double scale = 0.92 * std::min(kPanelWidth / (high.x() - low.x()), kPanelHeight / (high.y() - low.y()));
  const Eigen::Vector2d middle = 0.5 * (low.head<2>() + high.head<2>());
  const auto to_pixel = [=](const Eigen::Vector3d& s) {
    return Eigen::Vector3d(x0 + kPanelWidth / 2.0 + scale * (s.x() - middle.x()), kPanelHeight / 2.0 - scale * (s.y() - middle.y()), s.z());
  };
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    Eigen::Vector3d c[3];
    for (int k = 0; k < 3; ++k) c[k] = to_pixel(screen.row(mesh.F(f, k)).transpose());
    const double area = (c[1].x() - c[0].x()) * (c[2].y() - c[0].y()) - (c[2].x() - c[0].x()) * (c[1].y() - c[0].y());
    if (std::abs(area) < 1e-12) continue;
    const int px0 = std::max(x0, static_cast<int>(std::floor(std::min({c[0].x(), c[1].x(), c[2].x()}))));
    const int px1 = std::min(x0 + kPanelWidth - 1, static_cast<int>(std::ceil(std::max({c[0].x(), c[1].x(), c[2].x()}))));
    const int py0 = std::max(0, static_cast<int>(std::floor(std::min({c[0].y(), c[1].y(), c[2].y()}))));
    const int py1 = std::min(kPanelHeight - 1, static_cast<int>(std::ceil(std::max({c[0].y(), c[1].y(), c[2].y()}))));
    for (int py = py0; py <= py1; ++py) {
      for (int px = px0; px <= px1; ++px) {
        const double x = px + 0.5, y = py + 0.5;
        double w[3];
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3d& a = c[(k + 1) % 3];
          const Eigen::Vector3d& b = c[(k + 2) % 3];
          w[k] = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / area;
        }
        if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
        const double z = w[0] * c[0].z() + w[1] * c[1].z() + w[2] * c[2].z();
        const auto pixel = static_cast<size_t>(py * image.width + px);
        if (z >= image.depth[pixel]) continue;
        image.depth[pixel] = z;
        Eigen::Vector3d nrm = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) nrm += w[k] * corner_normal.row(3 * f + k).transpose();
        nrm.normalize();
        const Eigen::Vector3d reflected = camera.forward - 2.0 * camera.forward.dot(nrm) * nrm;
        const double elevation = std::asin(std::clamp(reflected.dot(stripe_axis), -1.0, 1.0));
        const bool light = static_cast<int>(std::floor(elevation / (std::numbers::pi / 18.0) + 100.0)) % 2 == 0;
        const double shade = 0.55 + 0.45 * std::abs(nrm.dot(camera.forward));
        const double grey = (light ? 245.0 : 35.0) * shade;
        for (int ch = 0; ch < 3; ++ch) image.rgb[3 * pixel + static_cast<size_t>(ch)] = static_cast<unsigned char>(grey);
      }
    }
  }
  return [=](const Eigen::Vector3d& p) { return to_pixel(Eigen::Vector3d(p.dot(camera.right), p.dot(camera.up), p.dot(camera.forward))); };
}

void render_panel(Image& image, int x0, const QuadMesh& control, int n, const Camera& camera, const Eigen::Vector3d& stripe_axis) {
  const QuadTopology topology = build_quad_topology(control);
  const std::vector<BezierPatch> patches = build_bezier_patches(control, topology);
  const SubdividedSurface surface = subdivide_bezier(control, n);
  const TriMesh mesh = triangulate_quads(surface.quads);
  Eigen::MatrixXd corner_normal(3 * mesh.triangle_count(), 3);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<size_t>(mesh.F(f, k));
      const PatchPoint point = evaluate_patch(patches[static_cast<size_t>(surface.source_face[v])], surface.source_uv(mesh.F(f, k), 0),
                                              surface.source_uv(mesh.F(f, k), 1));
      corner_normal.row(3 * f + k) = point.du.cross(point.dv).normalized().transpose();
    }
  }
  const auto to_screen = rasterise(image, x0, mesh, corner_normal, camera, stripe_axis);
  // Extraordinary control vertices (their limit positions) as red dots where visible.
  const SubdividedSurface corners = subdivide_bezier(control, 1);
  for (int v = 0; v < control.vertex_count(); ++v) {
    if (topology.valence(v) == 4) continue;
    const Eigen::Vector3d p = corners.quads.V.row(v).transpose();
    const Eigen::Vector3d s = to_screen(p);
    const int cx = static_cast<int>(s.x()), cy = static_cast<int>(s.y());
    if (cx < x0 || cx >= x0 + kPanelWidth || cy < 0 || cy >= kPanelHeight) continue;
    if (s.z() > image.depth[static_cast<size_t>(cy * image.width + cx)] + 1.0) continue;
    for (int dy = -3; dy <= 3; ++dy) {
      for (int dx = -3; dx <= 3; ++dx) {
        const int x = cx + dx, y = cy + dy;
        if (dx * dx + dy * dy > 10 || x < x0 || x >= x0 + kPanelWidth || y < 0 || y >= kPanelHeight) continue;
        const auto pixel = static_cast<size_t>(y * image.width + x);
        image.rgb[3 * pixel] = 220, image.rgb[3 * pixel + 1] = 20, image.rgb[3 * pixel + 2] = 20;
      }
    }
  }
}

// The generator's Bezier last (generate_last with LastSurface::Bezier, 50k triangles): normals averaged over each vertex's faces
// on the side, the cut plane's on the cap, so that the rim shows as the crease it is.
void render_generated(Image& image, int x0, LastParams params, const Camera& camera, const Eigen::Vector3d& stripe_axis) {
  params.surface = LastSurface::Bezier;
  const LastShape shape(params);
  const TriMesh mesh = generate_last(params).mesh;
  const Eigen::Vector3d cut = shape.top_cut_normal(), origin(0.0, 0.0, shape.top_cut_z_mm(0.0));
  const Eigen::MatrixXd face_normal = triangle_normals(mesh);
  const auto on_cap = [&](int f) {
    for (int k = 0; k < 3; ++k) {
      if (std::abs((mesh.V.row(mesh.F(f, k)).transpose() - origin).dot(cut)) > 1e-6) return false;
    }
    return true;
  };
  Eigen::MatrixXd vertex_normal = Eigen::MatrixXd::Zero(mesh.vertex_count(), 3);
  const Eigen::VectorXd area = triangle_areas(mesh);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    if (on_cap(f)) continue;
    for (int k = 0; k < 3; ++k) vertex_normal.row(mesh.F(f, k)) += area(f) * face_normal.row(f);
  }
  Eigen::MatrixXd corner_normal(3 * mesh.triangle_count(), 3);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    for (int k = 0; k < 3; ++k) {
      corner_normal.row(3 * f + k) = on_cap(f) ? Eigen::RowVector3d(cut.transpose()) : Eigen::RowVector3d(vertex_normal.row(mesh.F(f, k)).normalized());
    }
  }
  rasterise(image, x0, mesh, corner_normal, camera, stripe_axis);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path;
  int control_quads = 600;
  std::string view = "side";
  CLI::App app{"Reflection lines on the Bezier surface of a generated last's quad control mesh at n = 3 and n = 4, "
               "side by side, as a binary PPM"};
  app.add_option("OUT.ppm", out_path, "picture to write (binary PPM, 1280 x 420 pixels)")->required();
  app.add_option("control_quads", control_quads, "about this many quads in the control mesh")->capture_default_str();
  app.add_option("view", view, "side, toe, or generated (left panel: the generator's 50k-triangle Bezier last)")
      ->capture_default_str()
      ->check(CLI::IsMember({"side", "toe", "generated"}));
  CLI11_PARSE(app, argc, argv);
  const bool generated = view == "generated";
  const LastParams params = LastParams::for_eu_size(42, FootSide::Right);
  const LastShape shape(params);
  const QuadMesh control = last_control_mesh(shape, params, control_quads);
  Camera camera;
  // Looking down onto the lateral side (or onto the toe), slightly from the front.
  camera.forward = view == "generated" ? Eigen::Vector3d(-0.45, 0.70, -0.55).normalized() : view == "toe" ? Eigen::Vector3d(-0.75, 0.35, -0.56).normalized() : Eigen::Vector3d(-0.25, 0.80, -0.55).normalized();
  camera.right = camera.forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  camera.up = camera.right.cross(camera.forward);
  const Eigen::Vector3d stripe_axis = Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
  Image image(2 * kPanelWidth, kPanelHeight);
  if (generated) {
    // Left: the generated Bezier last (sharp flat top); right: the closed control mesh at n = 4 (rounded top).
    render_generated(image, 0, params, camera, stripe_axis);
  } else {
    render_panel(image, 0, control, 3, camera, stripe_axis);
  }
  render_panel(image, kPanelWidth, control, 4, camera, stripe_axis);
  std::ofstream out(out_path, std::ios::binary);
  out << "P6\n" << image.width << " " << image.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(image.rgb.data()), static_cast<std::streamsize>(image.rgb.size()));
  std::printf("wrote %s: %d control quads, %s (left) and n = 4 (right)\n", out_path.c_str(), control.quad_count(),
              generated ? "the generated Bezier last" : "n = 3");
  return out ? 0 : 1;
}
