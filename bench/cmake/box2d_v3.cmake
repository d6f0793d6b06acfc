# Box2D v3 as a peer in impulse-bench, from the source tree in
# IMPULSE_BOX2D_V3_SOURCE (never part of this repository).
#
# v3 is built twice as a static library with its own CMake and flags (Release,
# validation, samples, tests and benchmarks off): once with SSE2 (its default
# on x86-64) and once with BOX2D_AVX2. Both define the same C symbols, so each
# build's global symbols, and the calls to them in the adapter compiled for
# it, are renamed with a per-build prefix (objcopy --redefine-syms): both
# builds and Box2D 2.4.1 then link into the one impulse-bench binary and run
# side by side in one table.

include(ExternalProject)

if(NOT EXISTS ${IMPULSE_BOX2D_V3_SOURCE}/include/box2d/box2d.h)
  message(FATAL_ERROR "IMPULSE_BOX2D_V3_SOURCE=${IMPULSE_BOX2D_V3_SOURCE} is not a Box2D v3 source tree")
endif()
if(NOT CMAKE_NM OR NOT CMAKE_OBJCOPY)
  message(FATAL_ERROR "Box2D v3 in impulse-bench needs nm and objcopy (binutils)")
endif()

# Adds the v3 build `flavour` (sse2 or avx2) and links it, with its adapter,
# into `bench_target`.
function(add_box2d_v3_build bench_target flavour use_avx2)
  set(build_dir ${CMAKE_CURRENT_BINARY_DIR}/box2d-v3-${flavour})
  set(v3_lib ${build_dir}/src/libbox2d.a)
  ExternalProject_Add(box2d_v3_${flavour}
    SOURCE_DIR ${IMPULSE_BOX2D_V3_SOURCE}
    BINARY_DIR ${build_dir}
    CMAKE_ARGS -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=OFF -DBOX2D_AVX2=${use_avx2}
               -DBOX2D_VALIDATE=OFF -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF -DBOX2D_BENCHMARKS=OFF
               -DBOX2D_DOCS=OFF
    INSTALL_COMMAND ""
    BUILD_BYPRODUCTS ${v3_lib})

  set(adapter box2d_v3_${flavour}_adapter)
  add_library(${adapter} STATIC adapters/box2d_v3_adapter.cpp)
  target_compile_definitions(${adapter} PRIVATE BOX2D_V3_NAMESPACE=box2d_v3_${flavour})
  target_include_directories(${adapter} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  # v3's headers are not ours to keep warning-free.
  target_include_directories(${adapter} SYSTEM PRIVATE ${IMPULSE_BOX2D_V3_SOURCE}/include)
  target_link_libraries(${adapter} PRIVATE impulse_engine impulse_warnings)

  set(prefixed_v3 ${build_dir}/libbox2d_v3_${flavour}.a)
  set(prefixed_adapter ${build_dir}/libbox2d_v3_${flavour}_adapter.a)
  add_custom_command(
    OUTPUT ${prefixed_v3} ${prefixed_adapter}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cmake/prefix_box2d_v3_symbols.sh impulse_v3${flavour}_ ${CMAKE_NM}
            ${CMAKE_OBJCOPY} ${v3_lib} $<TARGET_FILE:${adapter}> ${prefixed_v3} ${prefixed_adapter}
    DEPENDS box2d_v3_${flavour} ${adapter} ${v3_lib} ${CMAKE_CURRENT_SOURCE_DIR}/cmake/prefix_box2d_v3_symbols.sh
    COMMENT "Prefixing Box2D v3 (${flavour}) symbols with impulse_v3${flavour}_")
  add_custom_target(box2d_v3_${flavour}_prefixed DEPENDS ${prefixed_v3} ${prefixed_adapter})

  add_dependencies(${bench_target} box2d_v3_${flavour}_prefixed)
  target_link_libraries(${bench_target} PRIVATE ${prefixed_adapter} ${prefixed_v3} m)
  set_property(TARGET ${bench_target} APPEND PROPERTY LINK_DEPENDS ${prefixed_v3} ${prefixed_adapter})
endfunction()
