/* placeholder */
#ifndef BRDF_LANE_PASS
#define SMITH_NZ 129
#define SMITH_NY 33
BRDF_CONST float smith_tab_blinn_phong[SMITH_NZ * SMITH_NY] = {0};
BRDF_CONST float smith_tab_gaussian[SMITH_NZ * SMITH_NY] = {0};
#endif
