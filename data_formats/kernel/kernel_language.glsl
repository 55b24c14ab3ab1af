// The GLSL side of skybake's kernel language (data_formats/kernel/
// kernel_language.h): the kernel files that follow compute in float.
#define Real float
#define Real2 vec2
#define Real3 vec3
#define SKYBAKE_KERNEL
#define SKYBAKE_PI 3.14159265358979323846
