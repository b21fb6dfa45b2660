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
message(STATUS "install, find_package and pkg-config: ${out}")
