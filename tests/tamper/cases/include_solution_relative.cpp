// Attack: the reference solution by a relative path, as from exercises/.
#include "../solutions/p1b.cpp"
