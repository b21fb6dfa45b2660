# Installs the build into a scratch prefix, then builds and runs an application against it
# twice: through find_package(ivshadow) and through pkg-config.
# Run with: cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P InstallTest.cmake
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
foreach(name TransparentShadowGroup SoTransparentShadowGroup DeepShadowLight PeelingSeparator)
  if(NOT EXISTS ${prefix}/lib/lib${name}.so)
    message(FATAL_ERROR "the install lacks lib${name}.so for Coin's loader")
  endif()
endforeach()

execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer
                        -B ${WORK_DIR}/consumer -DCMAKE_PREFIX_PATH=${prefix}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring against find_package(ivshadow) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer RESULT_VARIABLE status
                OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building against find_package(ivshadow) failed")
endif()
execute_process(COMMAND ${WORK_DIR}/consumer/consumer OUTPUT_VARIABLE out RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT out MATCHES "TransparentShadowGroup with 2 children")
  message(FATAL_ERROR "the CMake-built consumer failed: ${out}")
endif()

set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
execute_process(COMMAND pkg-config --cflags --libs ivshadow OUTPUT_VARIABLE flags
                RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT status EQUAL 0 OR NOT flags MATCHES "-livshadow")
  message(FATAL_ERROR "pkg-config ivshadow failed: ${flags}")
endif()
separate_arguments(flag_list UNIX_COMMAND "${flags}")
execute_process(COMMAND c++ -std=c++17 ${SOURCE_DIR}/tests/install/consumer/main.cpp ${flag_list}
                        -Wl,-rpath,${prefix}/lib -o ${WORK_DIR}/pkgconfig_consumer
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building with pkg-config flags failed")
endif()
execute_process(COMMAND ${WORK_DIR}/pkgconfig_consumer OUTPUT_VARIABLE out RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT out MATCHES "TransparentShadowGroup with 2 children")
  message(FATAL_ERROR "the pkg-config consumer failed: ${out}")
endif()

# The Python module from the prefix: it loads the installed plugin (so Coin knows the nodes)
# and runs the installed executable.
execute_process(COMMAND ${PIVY_PYTHON} -c "import pivy" RESULT_VARIABLE has_pivy
                OUTPUT_QUIET ERROR_QUIET)
if(has_pivy EQUAL 0)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  execute_process(
    COMMAND ${PIVY_PYTHON} -c "import os, ivshadow; from pivy import coin; assert not coin.SoType.fromName(coin.SbName('TransparentShadowGroup')).isBad(); print(ivshadow.__file__, os.path.realpath(ivshadow.library()), os.path.realpath(ivshadow.executable()), sep=chr(10))"
    OUTPUT_VARIABLE python_out ERROR_VARIABLE python_err RESULT_VARIABLE status)
  file(REAL_PATH ${prefix} real_prefix)
  string(REPLACE "\n" ";" python_lines "${python_out}")
  foreach(line IN LISTS python_lines)
    if(line AND NOT line MATCHES "^${real_prefix}/")
      message(FATAL_ERROR "the installed Python module uses ${line}, not the install's")
    endif()
  endforeach()
  if(NOT status EQUAL 0 OR NOT python_out MATCHES "libivshadow")
    message(FATAL_ERROR "import ivshadow from the install failed: ${python_out}${python_err}")
  endif()
  set(out "${out}; Python module ok")
else()
  message(STATUS "no pivy for ${PIVY_PYTHON}: the installed Python module is not imported")
endif()
message(STATUS "install, find_package and pkg-config: ${out}")
