#pragma once

#include <Inventor/SbColor.h>
#include <Inventor/SbVec3f.h>
#include <Inventor/elements/SoEnvironmentElement.h>

#include <cstdint>

namespace ivshadow {

// What SoEnvironmentElement holds in a state, read in one call.
struct EnvironmentValues {
  float ambientIntensity = 0.0f;
  SbColor ambientColour;
  SbVec3f attenuation;
  int32_t fogType = 0;
  SbColor fogColour;
  float fogVisibility = 0.0f;
  float fogStart = 0.0f;

  static EnvironmentValues of(SoState* state) {
    EnvironmentValues v;
    SoEnvironmentElement::get(state, v.ambientIntensity, v.ambientColour, v.attenuation, v.fogType,
                              v.fogColour, v.fogVisibility, v.fogStart);
    return v;
  }
};

}  // namespace ivshadow
