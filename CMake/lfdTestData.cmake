# Real test data (templeRing) through CMake's ExternalData, the VTK way: the
# repository holds content links (`<name>.sha512`, the file's SHA-512) and the
# data comes from an object store (`<store>/SHA512/<hash>`).
#
# The shared folder (LFD_SHARED_DATA_DIR, `../shared/data` by default, or the
# public templeRing.zip unpacked into it) is laid out by file name, not by
# hash. At configure time every content link whose object is in no store is
# looked up by name in that folder; a file whose SHA-512 matches its link is
# linked into a store in the build tree, so ExternalData then finds it like
# any other object. More stores or per-object URL templates can be given with
# -DExternalData_OBJECT_STORES=... / -DExternalData_URL_TEMPLATES=...
#
# A data folder whose objects cannot all be found is not referenced at all:
# ExternalData would otherwise fail the build. Its tests still run and report
# themselves skipped (return code 125) when they do not find their files.

include(ExternalData)

set(ExternalData_BINARY_ROOT "${CMAKE_BINARY_DIR}/ExternalData")
set(lfd_data_store "${CMAKE_BINARY_DIR}/ExternalData/Objects")
list(PREPEND ExternalData_OBJECT_STORES "${lfd_data_store}")

# lfd_test_data(<var> <folder> <regex>): <folder> is a source-tree folder of
# content links (relative to the source root) whose name is also its folder
# under LFD_SHARED_DATA_DIR; the links whose file name matches <regex> are
# resolved. Sets <var> to the build-tree folder that holds the data when all
# of it was found (the files appear there at build time, target lfdData).
function (lfd_test_data var folder regex)
  get_filename_component(shared_folder "${folder}" NAME)
  set(shared_folder "${LFD_SHARED_DATA_DIR}/${shared_folder}")
  file(GLOB links RELATIVE "${CMAKE_SOURCE_DIR}/${folder}" "${CMAKE_SOURCE_DIR}/${folder}/*.sha512")
  set(found 0)
  set(total 0)
  foreach (link IN LISTS links)
    string(REGEX REPLACE "\\.sha512$" "" name "${link}")
    if (NOT name MATCHES "^${regex}$")
      continue ()
    endif ()
    math(EXPR total "${total} + 1")
    file(STRINGS "${CMAKE_SOURCE_DIR}/${folder}/${link}" hash LIMIT_COUNT 1)
    set(in_store FALSE)
    foreach (store IN LISTS ExternalData_OBJECT_STORES)
      if (EXISTS "${store}/SHA512/${hash}")
        set(in_store TRUE)
      endif ()
    endforeach ()
    if (NOT in_store AND EXISTS "${shared_folder}/${name}")
      file(SHA512 "${shared_folder}/${name}" actual)
      if (actual STREQUAL hash)
        file(MAKE_DIRECTORY "${lfd_data_store}/SHA512")
        file(CREATE_LINK "${shared_folder}/${name}" "${lfd_data_store}/SHA512/${hash}"
          COPY_ON_ERROR SYMBOLIC)
        set(in_store TRUE)
      else ()
        message(WARNING "${shared_folder}/${name} does not match ${folder}/${link}: not used")
      endif ()
    endif ()
    if (in_store)
      math(EXPR found "${found} + 1")
    endif ()
  endforeach ()

  if (total EQUAL 0)
    message(FATAL_ERROR "lfd_test_data: no content link matches ${folder}/${regex}")
  elseif (found EQUAL total OR ExternalData_URL_TEMPLATES)
    ExternalData_Expand_Arguments(lfdData resolved
      "DATA{${CMAKE_SOURCE_DIR}/${folder}/,REGEX:${regex}}")
    message(STATUS "Test data ${folder}: ${found} of ${total} files in the object stores")
  else ()
    set(resolved "${ExternalData_BINARY_ROOT}/${folder}")
    message(STATUS "Test data ${folder}: ${found} of ${total} files found (looked in "
      "${shared_folder} and the object stores); the tests that need it are skipped")
  endif ()
  set("${var}" "${resolved}" PARENT_SCOPE)
endfunction ()
