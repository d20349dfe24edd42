# peer_bench: MeshEdit against OpenMesh and CGAL, included by tests/CMakeLists.txt. Both peers
# are optional and used by this program only: each is compiled in when found (scripts/setup_bench.sh
# installs Debian's libopenmesh-dev and libcgal-dev), and the program builds, runs and passes its smoke
# test with ours alone otherwise (or with -DMESHEDIT_BENCH_PEERS=OFF).
add_executable(peer_bench
  bench/peer_bench.cpp bench/peer_ours.cpp bench/peer_match.cpp bench/peer_memory.cpp bench/peer_table.cpp
  bench/peer_catmull_clark.cpp)
target_include_directories(peer_bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(peer_bench PRIVATE meshedit_core meshedit_warnings)
# Tiny run: keeps the program building and its match check passing, with or without the peers.
add_test(NAME peer_bench_smoke COMMAND peer_bench --faces 2000 --build-faces 2000 --levels 1 --reps 1)

option(MESHEDIT_BENCH_PEERS "peer_bench: compare against OpenMesh and CGAL when they are found" ON)

# OpenMesh: Debian ships a CMake config (targets OpenMeshCore/OpenMeshTools); elsewhere look for the
# header and library by hand. LoopT and CatmullClarkT are header-only over OpenMeshCore.
if(MESHEDIT_BENCH_PEERS)
  find_package(OpenMesh CONFIG QUIET)
  if(TARGET OpenMeshCore)
    set(MESHEDIT_OPENMESH_LIB OpenMeshCore)
  else()
    find_path(MESHEDIT_OPENMESH_INCLUDE OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh)
    find_library(MESHEDIT_OPENMESH_CORE OpenMeshCore)
    if(MESHEDIT_OPENMESH_INCLUDE AND MESHEDIT_OPENMESH_CORE)
      add_library(meshedit_openmesh INTERFACE)
      target_include_directories(meshedit_openmesh SYSTEM INTERFACE ${MESHEDIT_OPENMESH_INCLUDE})
      target_link_libraries(meshedit_openmesh INTERFACE ${MESHEDIT_OPENMESH_CORE})
      set(MESHEDIT_OPENMESH_LIB meshedit_openmesh)
    endif()
  endif()
endif()
# Each peer is compiled apart (an object library), so its flags (CGAL's -frounding-math) reach only its file.
function(meshedit_peer name source library define)
  add_library(${name} OBJECT ${source})
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE meshedit_core meshedit_warnings ${library})
  target_compile_definitions(${name} PUBLIC ${define})
  target_link_libraries(peer_bench PRIVATE ${name})
endfunction()

if(MESHEDIT_OPENMESH_LIB)
  message(STATUS "peer_bench: OpenMesh found, compared against")
  meshedit_peer(peer_bench_openmesh bench/peer_openmesh.cpp ${MESHEDIT_OPENMESH_LIB} MESHEDIT_HAVE_OPENMESH)
  meshedit_peer(peer_bench_openmesh_catmull_clark bench/peer_openmesh_catmull_clark.cpp ${MESHEDIT_OPENMESH_LIB}
                MESHEDIT_HAVE_OPENMESH)
else()
  message(STATUS "peer_bench: OpenMesh not used (scripts/setup_bench.sh installs it); ours runs without it")
endif()

# CGAL 5 is header-only; its config brings Boost (and GMP/MPFR when present).
if(MESHEDIT_BENCH_PEERS)
  find_package(CGAL CONFIG QUIET)
endif()
if(MESHEDIT_BENCH_PEERS AND TARGET CGAL::CGAL)
  message(STATUS "peer_bench: CGAL ${CGAL_VERSION} found, compared against")
  meshedit_peer(peer_bench_cgal bench/peer_cgal.cpp CGAL::CGAL MESHEDIT_HAVE_CGAL)
else()
  message(STATUS "peer_bench: CGAL not used (scripts/setup_bench.sh installs it); ours runs without it")
endif()
