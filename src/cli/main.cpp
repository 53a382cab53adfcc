#include <iostream>
int main() { std::cerr << "rackopt: not yet\n"; return 1; }
