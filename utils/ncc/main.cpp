#include <cstdio>
int main() { std::puts("ncc " NCC_VERSION); return 0; }
