// main() of one autograder variant: only the description differs (RAYLAB_VARIANT_DESCRIPTION).
int raylab_autograder_main(int argc, char** argv, const char* description);

int main(int argc, char** argv) { return raylab_autograder_main(argc, argv, RAYLAB_VARIANT_DESCRIPTION); }
