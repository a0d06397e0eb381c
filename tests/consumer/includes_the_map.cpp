/* Must not compile with mrpt_evidential::algebra alone (see CMakeLists.txt). */
#include <mrpt_evidential/CEvidentialGridMap2D.h>
int main() { return 0; }
