// The donor of the tests' precompiled header (tests/CMakeLists.txt, vibrofric_test_pch).
