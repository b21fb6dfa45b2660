// The one table of the shadow fields (nodes/ShadowFieldTable.h) against what it stands for:
// the fields a fresh node of each kind holds, read through Coin's field API; the FILE FORMAT
// blocks of the public headers, parsed; and the clamps at the table's ends.
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/ShadowFieldTable.h"
#include "scene/CoinRef.h"
#include "scene_input/CoinMessageCapture.h"

#include <Inventor/SbName.h>
#include <Inventor/SbString.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace ivshadow {
namespace {

// The four node kinds with shadow fields, each with its public header and whether it has the
// map's range fields.
struct NodeKind {
  const char* header;
  std::function<SoNode*()> make;
  bool mapRange;
};

std::vector<NodeKind> nodeKinds() {
  init();
  return {
      {"SoDeepShadowLight.h", [] { return new SoDeepShadowLight; }, true},
      {"SoDeepShadowSpotLight.h", [] { return new SoDeepShadowSpotLight; }, true},
      {"SoDeepShadowDirectionalLight.h", [] { return new SoDeepShadowDirectionalLight; }, false},
      {"SoTransparentShadowGroup.h", [] { return new SoTransparentShadowGroup; }, false}};
}

bool isMapRange(const ShadowFieldSpec& field) {
  return &field == &shadowField(ShadowFieldId::nearRadius) ||
         &field == &shadowField(ShadowFieldId::farRadius);
}

// A number as the FILE FORMAT blocks write it ("512", "0.1", "-1").
std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// A field's default as a file writes it: an enum's name, or the number.
std::string defaultText(const ShadowFieldSpec& field) {
  if (field.kind == ShadowFieldKind::Enum)
    return field.enumNames.names[std::size_t(field.defaultValue)];
  return numberText(field.defaultValue);
}

TEST(ShadowFieldTable, DefaultsAreWhatAFreshNodeOfEachKindHolds) {
  for (const NodeKind& kind : nodeKinds()) {
    const CoinRef<SoNode> node(kind.make());
    SCOPED_TRACE(kind.header);
    for (const ShadowFieldSpec& spec : kShadowFields) {
      SoField* field = node->getField(spec.name);
      if (isMapRange(spec) && !kind.mapRange) {
        EXPECT_EQ(field, nullptr) << spec.name;
        continue;
      }
      ASSERT_NE(field, nullptr) << spec.name;
      switch (spec.kind) {
        case ShadowFieldKind::Enum: {
          ASSERT_TRUE(field->isOfType(SoSFEnum::getClassTypeId())) << spec.name;
          const auto& value = static_cast<const SoSFEnum&>(*field);
          EXPECT_EQ(value.getValue(), int(spec.defaultValue)) << spec.name;
          ASSERT_EQ(std::size_t(value.getNumEnums()), spec.enumNames.count) << spec.name;
          for (int i = 0; i < value.getNumEnums(); ++i) {
            SbName name;
            EXPECT_EQ(value.getEnum(i, name), i) << spec.name;
            EXPECT_STREQ(name.getString(), spec.enumNames.names[i]) << spec.name;
          }
          break;
        }
        case ShadowFieldKind::Int:
          ASSERT_TRUE(field->isOfType(SoSFInt32::getClassTypeId())) << spec.name;
          EXPECT_EQ(static_cast<const SoSFInt32&>(*field).getValue(), int(spec.defaultValue))
              << spec.name;
          break;
        case ShadowFieldKind::Float:
          ASSERT_TRUE(field->isOfType(SoSFFloat::getClassTypeId())) << spec.name;
          EXPECT_EQ(static_cast<const SoSFFloat&>(*field).getValue(), float(spec.defaultValue))
              << spec.name;
          break;
      }
    }
  }
}

// A field's line in a FILE FORMAT block: its value, and the comment after it.
struct DocumentedField {
  std::string value;
  std::string comment;
};

std::map<std::string, DocumentedField> fileFormatBlock(const std::string& header) {
  std::ifstream in(std::string(IVSHADOW_SOURCE_DIR) + "/include/ivshadow/" + header);
  std::map<std::string, DocumentedField> fields;
  std::string line;
  bool inBlock = false, inCode = false;
  while (std::getline(in, line)) {
    if (line.find("FILE FORMAT/DEFAULTS:") != std::string::npos) inBlock = true;
    if (!inBlock) continue;
    if (line.find("\\endcode") != std::string::npos) break;
    if (line.find("\\code") != std::string::npos) {
      inCode = true;
      continue;
    }
    const std::size_t hash = line.find('#');
    const std::string text = line.substr(0, hash);
    std::istringstream words(text);
    std::string name, value, word;
    if (!inCode || !(words >> name) || name == "}" || text.find('{') != std::string::npos) continue;
    while (words >> word) value += (value.empty() ? "" : " ") + word;
    fields[name] = {value, hash == std::string::npos ? "" : line.substr(hash + 1)};
  }
  return fields;
}

// The text a fresh node's field writes, through Coin's field API.
std::string writtenValue(SoNode& node, const std::string& name) {
  SbString text;
  node.getField(name.c_str())->get(text);
  return text.getString();
}

// Whether a documented value is the one written: the same words, numbers to the digits the
// documentation gives (0.785398 for the 0.78539819 of pi / 4 in floats).
bool sameValue(const std::string& documented, const std::string& written) {
  std::istringstream a(documented), b(written);
  std::string x, y;
  while (a >> x) {
    if (!(b >> y)) return false;
    if (x == y) continue;
    char* xEnd = nullptr;
    char* yEnd = nullptr;
    const double u = std::strtod(x.c_str(), &xEnd), v = std::strtod(y.c_str(), &yEnd);
    if (*xEnd != '\0' || *yEnd != '\0' || std::abs(u - v) > 1e-6 * std::max(1.0, std::abs(v)))
      return false;
  }
  return !(b >> y);
}

TEST(ShadowFieldTable, FileFormatBlocksDocumentTheTablesDefaultsAndRanges) {
  const std::regex range(R"((-?[0-9.]+) \.\. ([0-9A-Z_.]+))");
  for (const NodeKind& kind : nodeKinds()) {
    SCOPED_TRACE(kind.header);
    const std::map<std::string, DocumentedField> documented = fileFormatBlock(kind.header);
    ASSERT_FALSE(documented.empty());
    for (const ShadowFieldSpec& spec : kShadowFields) {
      if (isMapRange(spec) && !kind.mapRange) continue;
      const auto found = documented.find(spec.name);
      ASSERT_NE(found, documented.end()) << spec.name << " is not documented";
      EXPECT_EQ(found->second.value, defaultText(spec)) << spec.name;
      // A range the nodes clamp to is stated, and what is stated is the table's.
      std::smatch ends;
      const bool stated = std::regex_search(found->second.comment, ends, range);
      EXPECT_EQ(stated, spec.low.kind == Bound::Clamp && spec.high.kind != Bound::Panel)
          << spec.name << ": " << found->second.comment;
      if (!stated) continue;
      EXPECT_EQ(std::stod(ends[1]), spec.low.value) << spec.name;
      EXPECT_EQ(ends[2], spec.high.kind == Bound::MaxTextureSize
                             ? std::string("GL_MAX_TEXTURE_SIZE")
                             : numberText(spec.high.value))
          << spec.name;
    }
    // Every documented default, shadow field or not, is the one a fresh node writes.
    const CoinRef<SoNode> node(kind.make());
    for (const auto& [name, field] : documented) {
      ASSERT_NE(node->getField(name.c_str()), nullptr) << name << " is not a field";
      EXPECT_PRED2(sameValue, field.value, writtenValue(*node.get(), name)) << name;
    }
  }
}

// Resolves `light`'s fields and collects what that said.
struct Resolved {
  DeepShadowSettings settings;
  std::vector<std::string> messages;
};

constexpr int kMaxTextureSize = 4096;

template <class Node>
Resolved resolve(const std::function<void(Node&)>& set) {
  init();
  const CoinRef<Node> node(new Node);
  node->setName("Lamp");
  // Each field is said where some method reads it: slices with OPACITY_MAP, filterSize with
  // PCF (the default).
  node->method = SoDeepShadowLight::OPACITY_MAP;
  set(*node.get());
  Resolved out;
  CoinMessageCapture capture;
  out.settings = resolveSettings(*node.get(), kMaxTextureSize);
  for (const auto& message : capture.messages()) out.messages.push_back(message.text);
  return out;
}

// The integer fields' settings, and the int a setting holds for each.
struct IntField {
  ShadowFieldId id;
  std::function<void(SoDeepShadowLight&, int)> set;
  std::function<int(const DeepShadowSettings&)> get;
};

std::vector<IntField> intFields() {
  return {
      {ShadowFieldId::resolution, [](SoDeepShadowLight& l, int v) { l.resolution = v; },
       [](const DeepShadowSettings& s) { return s.resolution; }},
      {ShadowFieldId::maxLayers, [](SoDeepShadowLight& l, int v) { l.maxLayers = v; },
       [](const DeepShadowSettings& s) { return s.maxLayers; }},
      {ShadowFieldId::slices, [](SoDeepShadowLight& l, int v) { l.slices = v; },
       [](const DeepShadowSettings& s) { return s.slices; }},
      {ShadowFieldId::filterSize, [](SoDeepShadowLight& l, int v) { l.filterSize = v; },
       [](const DeepShadowSettings& s) { return s.filterWidth; }},
  };
}

TEST(ShadowFieldTable, IntegerFieldsAreClampedAtTheTablesEndsWithOneWarning) {
  std::size_t checked = 0;
  for (const IntField& field : intFields()) {
    const ShadowFieldSpec& spec = shadowField(field.id);
    SCOPED_TRACE(spec.name);
    ASSERT_EQ(spec.kind, ShadowFieldKind::Int);
    const int low = int(spec.low.value);
    const int high =
        spec.high.kind == Bound::MaxTextureSize ? kMaxTextureSize : int(spec.high.value);
    for (const int inside : {low, high}) {
      const Resolved r =
          resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) { field.set(l, inside); });
      EXPECT_EQ(field.get(r.settings), inside);
      EXPECT_TRUE(r.messages.empty()) << r.messages.front();
    }
    for (const auto& [outside, clamped] : {std::pair{low - 1, low}, std::pair{high + 1, high}}) {
      const Resolved r =
          resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) { field.set(l, outside); });
      EXPECT_EQ(field.get(r.settings), clamped);
      ASSERT_EQ(r.messages.size(), 1u);
      const std::string said = std::string("field ") + spec.name + " is " +
                               std::to_string(outside) + ", outside " + std::to_string(low) + ".." +
                               std::to_string(high) + "; using " + std::to_string(clamped);
      EXPECT_NE(r.messages[0].find(said), std::string::npos) << r.messages[0];
    }
    ++checked;
  }
  std::size_t clamped = 0;
  for (const ShadowFieldSpec& spec : kShadowFields)
    clamped += spec.kind == ShadowFieldKind::Int && spec.low.kind == Bound::Clamp;
  EXPECT_EQ(checked, clamped) << "an integer field of the table is not checked here";
}

TEST(ShadowFieldTable, BiasIsClampedAtTheTablesLowEndAndNotAboveIt) {
  const ShadowFieldSpec& bias = shadowField(ShadowFieldId::bias);
  ASSERT_EQ(bias.low.kind, Bound::Clamp);
  const float low = float(bias.low.value);
  Resolved r = resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) { l.bias = low; });
  EXPECT_EQ(r.settings.bias, low);
  EXPECT_TRUE(r.messages.empty());
  r = resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) { l.bias = low - 0.5f; });
  EXPECT_EQ(r.settings.bias, low);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_NE(r.messages[0].find("field bias is negative; using 0"), std::string::npos);
  // The panel's end is not the nodes': a wider bias is taken as it is.
  ASSERT_EQ(bias.high.kind, Bound::Panel);
  const float above = float(bias.high.value) * 2.0f;
  r = resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) { l.bias = above; });
  EXPECT_EQ(r.settings.bias, above);
  EXPECT_TRUE(r.messages.empty());
}

TEST(ShadowFieldTable, FloatFieldsThatAreNotNumbersTakeTheTablesDefault) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Resolved r = resolve<SoDeepShadowLight>([&](SoDeepShadowLight& l) {
    l.bias = nan;
    l.nearRadius = nan;
    l.farRadius = nan;
  });
  EXPECT_EQ(r.settings.bias, float(shadowField(ShadowFieldId::bias).defaultValue));
  EXPECT_EQ(r.settings.nearRadius, float(shadowField(ShadowFieldId::nearRadius).defaultValue));
  EXPECT_EQ(r.settings.farRadius, float(shadowField(ShadowFieldId::farRadius).defaultValue));
  EXPECT_EQ(r.messages.size(), 3u);
}

TEST(ShadowFieldTable, TheGroupsFieldsAreClampedAsTheLightsAre) {
  const ShadowFieldSpec& layers = shadowField(ShadowFieldId::maxLayers);
  const int high = int(layers.high.value);
  const Resolved r = resolve<SoTransparentShadowGroup>(
      [&](SoTransparentShadowGroup& g) { g.maxLayers = high + 1; });
  EXPECT_EQ(r.settings.maxLayers, high);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_NE(r.messages[0].find("field maxLayers is " + std::to_string(high + 1)),
            std::string::npos);
}

}  // namespace
}  // namespace ivshadow
