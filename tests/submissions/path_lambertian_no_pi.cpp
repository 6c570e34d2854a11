// Grader self-test submission (stage 08_direct_light's lambertian_f, as stage 09 grades it): f =
// albedo, 1 / pi missing, as in direct_lambertian_no_pi. With roulette (p = 0.5) each bounce
// weighs pi a / p = 3.14, so the furnace's mean diverges (thousands instead of 2) and its pixels
// reach millions: a t-test alone let FurnaceWithRoulette pass, since the standard error was as
// huge as the mean. Its spread test must fail it, naming lambertian_f.
#include "direct_lambertian_no_pi.cpp"
