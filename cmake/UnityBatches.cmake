# mx_unity_batches(target): with MX_UNITY_TESTS, the target's sources compile eight to a translation
# unit. The test and benchmark programs parse the same Qt and project headers in every file; batching
# them nearly halves the test command's build. Their file-scope names must therefore be unique within a
# folder. The asan preset turns it off, so that every file still compiles on its own there.
function(mx_unity_batches target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${MX_UNITY_TESTS} UNITY_BUILD_BATCH_SIZE 8)
  # GCC takes an included .cpp for a header: a lambda that captures a file-local type would warn.
  if(MX_UNITY_TESTS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
endfunction()
