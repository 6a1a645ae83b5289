#include "basis/catmull_clark/stam.hpp"
