# The shared library acoustic_liggghts: the C++98 facade of the ACOUSTIC
# numerics (lib/acoustic/acoustic_facade.h, acoustic_gathered_drive.h,
# acoustic_gathered_modes.h, acoustic_gathered_pulse.h, acoustic_contact_factor.h), which the LIGGGHTS styles include and link
# (-lacoustic_liggghts), built on the static acoustic_numerics (position
# independent code).  It exports the facade's functions only: the numerics,
# Eigen's instances and the rest are hidden (-fvisibility=hidden, and
# --exclude-libs for the static library linked in), so that nothing of them
# can clash with a symbol of LIGGGHTS.  A consumer's include path is
# lib/acoustic: the facade headers include <string> and <vector> only.
# Result: libacoustic_liggghts.so in the top build directory.
add_library(acoustic_liggghts SHARED ${ACOUSTIC_FACADE_SOURCES})
target_link_libraries(acoustic_liggghts PRIVATE acoustic_numerics)
target_include_directories(acoustic_liggghts INTERFACE ${PROJECT_SOURCE_DIR}/lib/acoustic)
target_compile_options(acoustic_liggghts PRIVATE -Wall -Wextra)
set_target_properties(acoustic_liggghts PROPERTIES CXX_VISIBILITY_PRESET hidden
                      VISIBILITY_INLINES_HIDDEN ON)
target_link_options(acoustic_liggghts PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
