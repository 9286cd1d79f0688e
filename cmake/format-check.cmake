# CTest test format_check: every C++ file in the project's source dirs must already be formatted
# by the committed .clang-format. Usage: cmake -DCLANG_FORMAT=<exe> -DSOURCE_DIR=<root> -P this
set(files "")
foreach(dir include tests bench examples tools fuzz)
    file(GLOB_RECURSE found "${SOURCE_DIR}/${dir}/*.hpp" "${SOURCE_DIR}/${dir}/*.cpp"
                            "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.cc")
    list(APPEND files ${found})
endforeach()
list(SORT files)
list(LENGTH files count)
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run -Werror ${files} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "clang-format: some of the ${count} files are not formatted "
                        "(fix with: clang-format -i <file>)")
endif()
message(STATUS "clang-format: ${count} files formatted")
