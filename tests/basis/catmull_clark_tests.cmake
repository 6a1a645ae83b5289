# Tests of the Catmull–Clark space (registered with iga_add_test).
