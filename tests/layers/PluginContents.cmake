# The plugin library holds the nodes and their layers only, and exports only what is marked
# (docs/ARCHITECTURE.md): Coin's loader entry points and the public API are exported, internals
# that no tool calls are not, and no code of a tool layer is inside at all.
# Run with: cmake -DLIBRARY=<path of libivshadow.so> -P PluginContents.cmake
find_program(NM nm REQUIRED)
find_program(READELF readelf REQUIRED)
execute_process(COMMAND ${NM} -C --defined-only ${LIBRARY} OUTPUT_VARIABLE all_symbols
                RESULT_VARIABLE status)
execute_process(COMMAND ${NM} -C -D --defined-only ${LIBRARY} OUTPUT_VARIABLE exported)
execute_process(COMMAND ${READELF} -d ${LIBRARY} OUTPUT_VARIABLE dynamic)
if(NOT status EQUAL 0 OR all_symbols STREQUAL "")
  message(FATAL_ERROR "cannot read the symbols of ${LIBRARY}")
endif()

set(problems "")
foreach(name SoTransparentShadowGroup::initClass TransparentShadowGroup::initClass
             SoDeepShadowLight::initClass DeepShadowLight::initClass
             SoPeelingSeparator::initClass PeelingSeparator::initClass
             SoDeepShadowSpotLight::initClass DeepShadowSpotLight::initClass
             SoDeepShadowDirectionalLight::initClass DeepShadowDirectionalLight::initClass
             "ivshadow::init[(]"
             ivshadow::collectDeepShadowStatistics ivshadow::collectPeelStatistics)
  if(NOT exported MATCHES "${name}")
    string(APPEND problems "  not exported: ${name}\n")
  endif()
endforeach()
# Internals that only the plugin itself uses stay hidden (DeepShadowPass is exported for its
# GL-layer test, tests/gl/MapFragmentListsGLTest.cpp; the map and its lists are not).
foreach(name ivshadow::DeepShadowMap:: ivshadow::MapFragmentLists:: ivshadow::PeelPass::
             ivshadow::ShadingUniforms::
             ivshadow::TransparentShadowGroupImpl::render)
  if(exported MATCHES "${name}")
    string(APPEND problems "  exported but internal: ${name}\n")
  endif()
endforeach()
# Tool layers: headless rendering, scene and image files, variants, the reference renderer.
foreach(name ivshadow::EglHeadlessContext ivshadow::OffscreenRenderer ivshadow::writePng
             ivshadow::loadScene ivshadow::parseVariants ivshadow::renderReference)
  if(all_symbols MATCHES "${name}")
    string(APPEND problems "  a tool layer is inside: ${name}\n")
  endif()
endforeach()
if(dynamic MATCHES "libpng")
  string(APPEND problems "  links libpng\n")
endif()
if(problems)
  message(FATAL_ERROR "${LIBRARY}:\n${problems}")
endif()
message(STATUS "plugin library: public API and loader entry points exported, no tool layer inside")
