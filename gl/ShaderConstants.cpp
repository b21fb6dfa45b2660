#include "gl/ShaderConstants.h"

#include "gl/GlLimits.h"
#include "gl/LightSlotFields.h"

#include <iomanip>
#include <limits>
#include <sstream>

namespace ivshadow {
namespace {

// "vec3[6](vec3(1, 0, 0), ...)": a GLSL array constructor of the six face vectors.
std::string faceArray(const FaceVectors& vectors) {
  std::ostringstream text;
  text << "vec3[6](";
  for (std::size_t face = 0; face < vectors.size(); ++face) {
    const auto& v = vectors[face];
    text << (face > 0 ? ", " : "") << "vec3(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  }
  text << ")";
  return text.str();
}

// The per-light uniform arrays of LightSlotFields.h, on one line: "uniform vec3 uMapLight[8]; ...".
std::string lightSlotDeclarations() {
  std::ostringstream text;
#define IVSHADOW_LIGHT_SLOT_DECLARATION(glslType, perSlot, Element, member, uniform, initial) \
  text << "uniform " #glslType " " #uniform "[" << kMaxGlLights * (perSlot) << "]; ";
  IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_LIGHT_SLOT_DECLARATION)
#undef IVSHADOW_LIGHT_SLOT_DECLARATION
  return text.str();
}

}  // namespace

std::string shaderConstantDefines() {
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<float>::max_digits10)
       << "#define IVSHADOW_MAX_LIGHTS " << kMaxGlLights << "\n"
       << "#define IVSHADOW_OPAQUE_ALPHA " << kOpaqueAlpha << "\n"
       << "#define IVSHADOW_MIN_TRANSMITTANCE " << kMinTransmittance << "\n"
       << "#define IVSHADOW_OPACITY_SLICES_PER_DRAW " << kOpacitySlicesPerDraw << "\n"
       << "#define IVSHADOW_OPACITY_NO_OPAQUE " << kOpacityNoOpaque << "\n"
       << "#define IVSHADOW_OPACITY_EMPTY_SLICE " << kOpacityEmptySlice << "\n"
       << "#define IVSHADOW_FACE_AXIS " << faceArray(kFaceAxis) << "\n"
       << "#define IVSHADOW_FACE_RIGHT " << faceArray(kFaceRight) << "\n"
       << "#define IVSHADOW_FACE_UP " << faceArray(kFaceUp) << "\n"
       << "#define IVSHADOW_MAP_FLAGS_BINDING " << kMapFlagsBinding << "\n"
       << "#define IVSHADOW_PEEL_PROGRESS_BINDING " << kPeelProgressBinding << "\n"
       << "#define IVSHADOW_FRAGMENT_LIST_BINDING " << kFragmentListBinding << "\n"
       << "#define IVSHADOW_MAP_MERGE_QUEUE_BINDING " << kMapMergeQueueBinding << "\n"
       << "#define IVSHADOW_MAP_MERGE_GROUP_SIZE " << kMapMergeGroupSize << "\n"
       << "#define IVSHADOW_FRAGMENT_HEADS_UNIT " << kFragmentHeadsUnit << "\n"
       << "#define IVSHADOW_FRAGMENT_COUNTS_UNIT " << kFragmentCountsUnit << "\n"
       << "#define IVSHADOW_MAX_FRAGMENTS_PER_PIXEL " << kMaxFragmentsPerPixel << "\n"
       << "#define IVSHADOW_MAP_LAYER_DEPTH_UNIT " << kMapLayerDepthUnit << "\n"
       << "#define IVSHADOW_MAP_LAYER_VISIBILITY_UNIT " << kMapLayerVisibilityUnit << "\n"
       << "#define IVSHADOW_MAP_RESOLVE_GROUP_SIZE " << kMapResolveGroupSize << "\n"
       << "#define IVSHADOW_MAP_FACE_FLAGS " << kMapFaceFlags << "\n"
       << "#define IVSHADOW_MAX_MAP_LAYERS " << kMaxMapLayers << "\n"
       << "#define IVSHADOW_MAX_SCREEN_LAYERS " << kMaxScreenLayers << "\n"
       << "#define IVSHADOW_VOLUME_DEPTH_TOLERANCE " << kVolumeDepthTolerance << "\n"
       << "#define IVSHADOW_MAP_CUBE " << int(MapProjection::Cube) << "\n"
       << "#define IVSHADOW_MAP_PERSPECTIVE " << int(MapProjection::Perspective) << "\n"
       << "#define IVSHADOW_MAP_ORTHOGRAPHIC " << int(MapProjection::Orthographic) << "\n"
       << "#define IVSHADOW_BOUNCE_TEXELS_PER_LIGHT " << kBounceTexelsPerLight << "\n"
       << "#define IVSHADOW_ISM_POINT_SIZE float(" << kIsmPointSize << ")\n"
       << "#define IVSHADOW_ISM_EMPTY " << kIsmEmpty << "\n"
       << "#define IVSHADOW_ISM_BIAS " << kIsmBias << "\n"
       << "#define IVSHADOW_ISM_NORMAL_OFFSET " << kIsmNormalOffset * 4.0f << "\n"
       << "#define IVSHADOW_ISM_GROUP_SIZE " << kIsmGroupSize << "\n"
       << "#define IVSHADOW_ISM_READ_UNIT " << kIsmReadUnit << "\n"
       << "#define IVSHADOW_ISM_WRITE_UNIT " << kIsmWriteUnit << "\n"
       << "#define IVSHADOW_INVERSE_PI " << 0.318309886f << "\n"
       << "#define IVSHADOW_COLOUR_MONOCHROME " << int(ShadowColourModel::Monochrome) << "\n"
       << "#define IVSHADOW_COLOUR_SATURATE " << int(ShadowColourModel::Saturate) << "\n"
       << "#define IVSHADOW_COLOUR_POWER " << int(ShadowColourModel::Power) << "\n"
       << "#define IVSHADOW_LIGHT_SLOT_UNIFORMS " << lightSlotDeclarations() << "\n";
  return text.str();
}

}  // namespace ivshadow
