#pragma once
// Placeholder: Stam's evaluation of a Catmull–Clark patch at an interior extraordinary vertex.
