// The source of numlab_test_pch (tests/CMakeLists.txt): the target exists to build the tests'
// precompiled header, which the test executables reuse; this file has nothing else to compile.
