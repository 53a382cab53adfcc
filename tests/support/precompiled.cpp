// Holder of the test programs' shared precompiled header (CMakeLists.txt,
// rackopt_test_pch): CMake builds the header with this file's flags, and every
// test program, compiled with the same flags, reuses it.
