#include "tests/support/RandomScene.h"

#include <random>
#include <sstream>

namespace ivshadow::test {
namespace {

class Writer {
 public:
  explicit Writer(std::uint32_t seed) : random_(seed) {}

  std::string scene() {
    out_ << "#Inventor V2.1 ascii\nSeparator {\n";
    camera();
    if (chance(0.3)) out_ << "DirectionalLight { direction 0.2 -0.3 -1 intensity 0.4 }\n";
    group(0);
    if (chance(0.3)) lines();
    out_ << "}\n";
    return out_.str();
  }

 private:
  bool chance(double p) { return std::bernoulli_distribution(p)(random_); }
  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random_);
  }
  int pick(int count) { return std::uniform_int_distribution<int>(0, count - 1)(random_); }

  void camera() {
    const char* planes[] = {"nearDistance 1 farDistance 20", "nearDistance 1e-6 farDistance 20",
                            "nearDistance 0.01 farDistance 1e7"};
    const char* plane = planes[chance(0.7) ? 0 : 1 + pick(2)];
    // Moved a little per scene: one camera for all would put the same edges at the same
    // places in every picture.
    out_ << (chance(0.5) ? "PerspectiveCamera {" : "OrthographicCamera { height 5") << " position "
         << uniform(-0.3, 0.3) << ' ' << uniform(-2.8, -2.2) << ' ' << uniform(5.5, 6.5)
         << " orientation 1 0 0 " << uniform(0.3, 0.5) << ' ' << plane << " }\n";
  }

  void light() {
    const double x = uniform(-1.5, 1.5), y = uniform(-1.5, 1.5), z = uniform(2.0, 4.0);
    switch (pick(6)) {
      case 0:
        out_ << "PointLight { location " << x << ' ' << y << ' ' << z << " }\n";
        break;
      case 1:
        out_ << "SpotLight { location " << x << ' ' << y << ' ' << z << " direction " << -x * 0.3
             << ' ' << -y * 0.3 << " -1 cutOffAngle 0.7 }\n";
        break;
      case 2:
        out_ << "DirectionalLight { direction " << -x * 0.3 << ' ' << -y * 0.3 << " -1 }\n";
        break;
      case 3:
        out_ << "DeepShadowLight { location " << x << ' ' << y << ' ' << z << " }\n";
        break;
      case 4:
        out_ << "DeepShadowSpotLight { location " << x << ' ' << y << ' ' << z << " direction "
             << -x * 0.3 << ' ' << -y * 0.3 << " -1 cutOffAngle 0.8 }\n";
        break;
      default:
        out_ << "DeepShadowDirectionalLight { direction " << -x * 0.3 << ' ' << -y * 0.3
             << " -1 }\n";
    }
  }

  void shape() {
    out_ << "Separator { Translation { translation " << uniform(-1.2, 1.2) << ' '
         << uniform(-1.2, 1.2) << ' ' << uniform(0.3, 1.2) << " }\n";
    const bool glass = chance(0.6);
    out_ << "Material { diffuseColor " << uniform(0, 1) << ' ' << uniform(0, 1) << ' '
         << uniform(0, 1) << " transparency " << (glass ? uniform(0.2, 0.8) : 0.0) << " }\n";
    const char* shapes[] = {"Cube { width 0.5 height 0.5 depth 0.2 }", "Sphere { radius 0.3 }",
                            "Cone { bottomRadius 0.3 height 0.5 }",
                            "Coordinate3 { point [ -0.3 -0.3 0, 0.3 -0.3 0, 0.3 0.3 0, -0.3 0.3 0 "
                            "] } FaceSet { numVertices 4 }"};
    out_ << shapes[pick(4)] << "\n}\n";
  }

  void lines() {
    out_ << "Separator { LightModel { model BASE_COLOR } BaseColor { rgb 1 1 0 }\n"
         << "Coordinate3 { point [ -1 -1 0.05, 1 1 0.05, 1 -1 0.05 ] } LineSet { numVertices 3 }\n";
    if (chance(0.5)) out_ << "Translation { translation -1 1 0.5 } Text2 { string \"ivshadow\" }\n";
    out_ << "}\n";
  }

  void group(int depth) {
    out_ << "TransparentShadowGroup {\n";
    const int lights = 1 + pick(3);
    for (int i = 0; i < lights; ++i) light();
    if (depth == 0)
      out_
          << "Material { diffuseColor 0.8 0.8 0.8 }\n"
          << "Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] } FaceSet { numVertices 4 }\n";
    const int shapes = 1 + pick(3);
    for (int i = 0; i < shapes; ++i) shape();
    // A light that ends with its separator: it lights the shape beside it, nothing after.
    if (chance(0.25)) {
      out_ << "Separator {\n";
      light();
      shape();
      out_ << "}\n";
    }
    if (chance(0.3)) {
      out_ << "DEF Shared" << depth << " Separator { Translation { translation 0.6 0.6 0.8 }\n";
      shape();
      out_ << "}\nSeparator { Translation { translation -1.2 -0.3 0 } USE Shared" << depth
           << " }\n";
    }
    if (chance(0.3)) {
      out_ << "Separator { Separator { PeelingSeparator {\n";
      shape();
      out_ << "} } }\n";
    }
    if (depth == 0 && chance(0.4)) group(1);
    if (chance(0.2)) lines();
    out_ << "}\n";
  }

  std::mt19937 random_;
  std::ostringstream out_;
};

}  // namespace

std::string randomScene(std::uint32_t seed) {
  return Writer(seed).scene();
}

}  // namespace ivshadow::test
