#include "ivshadow/IvShadowInit.h"
#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <string>

namespace ivshadow {
namespace {

CoinRef<SoSeparator> read(const std::string& body) {
  init();
  const std::string text = "#Inventor V2.1 ascii\nSeparator { " + body + " }\n";
  SoInput input;
  input.setBuffer(text.data(), text.size());
  return CoinRef<SoSeparator>(SoDB::readAll(&input));
}

SbBox3f castersBounds(const std::string& body) {
  CoinRef<SoSeparator> root = read(body);
  EXPECT_TRUE(root);
  const SceneTriangles triangles = extractShadowCasters(root.get());
  EXPECT_GT(triangles.triangleCount(), 0u) << body;
  return triangles.bounds;
}

// Glyph outlines are floats scaled by the size: a thousandth of the size is far below any
// difference the double scaling makes (a factor of the size itself).
constexpr float kOutline = 0.01f;

void expectSameXy(const SbBox3f& actual, const SbBox3f& expected, const std::string& what) {
  for (int axis : {0, 1}) {
    EXPECT_NEAR(actual.getMin()[axis], expected.getMin()[axis], kOutline) << what << " " << axis;
    EXPECT_NEAR(actual.getMax()[axis], expected.getMax()[axis], kOutline) << what << " " << axis;
  }
}

// The sides extrude the glyphs' outlines, so they span the front faces' x and y, whatever the
// font size and however many glyphs (Coin generated them at the size squared: with size 10,
// ten times too far out). Their depth is one unit at any size, in GL as in the triangles.
TEST(Text3Sides, TheSidesSpanTheFrontFacesAtAnyFontSize) {
  for (const char* size : {"1", "10", "0.25"}) {
    const std::string font = std::string("Font { size ") + size + " } ";
    for (const char* string : {"I", "HI"}) {
      const std::string text = std::string("string \"") + string + "\"";
      const SbBox3f front = castersBounds(font + "Text3 { " + text + " parts FRONT }");
      const SbBox3f all = castersBounds(font + "Text3 { " + text + " parts ALL }");
      const SbBox3f sides = castersBounds(font + "Text3 { " + text + " parts SIDES }");
      expectSameXy(all, front, std::string("ALL, size ") + size + ", " + string);
      expectSameXy(sides, front, std::string("SIDES, size ") + size + ", " + string);
      EXPECT_NEAR(sides.getMin()[2], -1.0f, 1e-6f);
      EXPECT_NEAR(sides.getMax()[2], 0.0f, 1e-6f);
    }
  }
}

// Coin's own bounding box of the text (SoText3::computeBBox, which scales the glyphs once and
// spans their advances, so it may be a little wider than the outlines) holds the triangles:
// an answer computed without them.
TEST(Text3Sides, TheTrianglesLieInCoinsBoundingBoxOfTheText) {
  const std::string body = "Font { size 10 } Text3 { string \"HI\" parts ALL }";
  CoinRef<SoSeparator> root = read(body);
  SoGetBoundingBoxAction action{SbViewportRegion(100, 100)};
  action.apply(root.get());
  const SbBox3f coin = action.getBoundingBox();
  const SbBox3f triangles = castersBounds(body);
  for (int axis : {0, 1, 2}) {
    EXPECT_GE(triangles.getMin()[axis], coin.getMin()[axis] - kOutline) << axis;
    EXPECT_LE(triangles.getMax()[axis], coin.getMax()[axis] + kOutline) << axis;
  }
}

// The correction ends with the text: what follows it in the same separator keeps its font
// size and its transformation.
TEST(Text3Sides, WhatFollowsTheTextIsWhereItWas) {
  const SbBox3f cube = castersBounds(
      "Font { size 10 } Text3 { string \"I\" parts ALL } Translation { translation 100 0 0 } "
      "Cube { width 2 height 2 depth 2 }");
  const SbBox3f one = castersBounds("Font { size 10 } Text3 { string \"I\" parts FRONT }");
  EXPECT_NEAR(cube.getMax()[0], 101.0f, 1e-4f) << "the cube, moved and not scaled";
  EXPECT_NEAR(cube.getMax()[1], one.getMax()[1], kOutline) << "the text's top";
  const SbBox3f after = castersBounds(
      "Font { size 10 } Text3 { string \"I\" parts ALL } Text3 { string \"I\" parts FRONT }");
  expectSameXy(after, one, "a second text at the same size");
}

}  // namespace
}  // namespace ivshadow
