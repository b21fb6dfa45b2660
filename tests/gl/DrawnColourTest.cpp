// A diffuse colour outside 0..1 (issue 36): Coin packs colours into 8 bits a channel without
// clamping them (SbColor::getPackedValue), so 1.7 is drawn as 0.7 and a green of 1.7 carries
// one step into red; the reference drew the float. Every path draws what plain Coin draws,
// worked out here by hand from the packing, and says so once.
#include "ivshadow/IvShadowInit.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/ShadowScene.h"

#include <gtest/gtest.h>

#include <array>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 16;

// An unlit square filling the view in `colour`: its pixels are the colour GL is sent.
std::string square(const char* colour, const char* group) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2 }\n"
     << (*group == '\0' ? std::string("Separator {")
                        : std::string("TransparentShadowGroup { ") + group)
     << "\nLightModel { model BASE_COLOR }\nMaterial { diffuseColor " << colour << " }\n"
     << "Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }\nFaceSet { numVertices 4 }\n"
     << "}\n}\n";
  return iv.str();
}

struct Case {
  const char* colour;
  std::array<int, 3> drawn;
};

// (uint32) (c * 255 + 0.5) shifted into its byte of RGBA and OR-ed with the others: 1.7 gives
// 434 = 0x1B2, whose low byte 0xB2 = 178 is the channel and whose ninth bit is OR-ed into the
// channel above (none above red: it is shifted out). 0.4 packs to 102, even: the bit shows.
const Case kCases[] = {{"1.7 0.3 0.3", {178, 77, 77}}, {"0.4 1.7 0.2", {103, 178, 51}}};

TEST(DrawnColour, EveryPathDrawsAColourAboveOneAsCoinPacksIt) {
  init();
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.colour);
    const Image coin = renderIv(square(c.colour, ""), kSize);
    for (int channel = 0; channel < 3; ++channel)
      EXPECT_EQ(coin.pixel(8, 8)[channel], c.drawn[std::size_t(channel)]) << "plain Coin";
    CoinMessageCapture messages;
    const Image pictures[] = {renderIv(square(c.colour, "renderer RASTER"), kSize),
                              renderIv(square(c.colour, "renderer TRACER"), kSize),
                              referenceIv(square(c.colour, "renderer RASTER"), kSize)};
    for (const Image& image : pictures)
      for (int channel = 0; channel < 3; ++channel)
        // One 8-bit step: the tracer's float round trip.
        EXPECT_NEAR(image.pixel(8, 8)[channel], c.drawn[std::size_t(channel)], 1.0)
            << "path " << (&image - pictures);
  }
}

TEST(DrawnColour, AColourOutsideZeroToOneIsReportedOnce) {
  init();
  CoinMessageCapture messages;
  referenceIv(square("1.7 0.3 0.3", ""), kSize);
  referenceIv(square("1.7 0.3 0.3", ""), kSize);
  int said = 0;
  for (const CoinMessageCapture::Message& m : messages.messages())
    said += m.text.find("a diffuse colour of 1.7") != std::string::npos ? 1 : 0;
  EXPECT_EQ(said, 1);
}

}  // namespace
}  // namespace ivshadow::test
