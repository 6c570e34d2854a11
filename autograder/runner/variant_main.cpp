// main() of one autograder variant: only the description differs (RAYLAB_VARIANT_DESCRIPTION, and
// RAYLAB_VARIANT_DESCRIPTION_ZH for --lang zh).
int raylab_autograder_main(int argc, char** argv, const char* description, const char* description_zh);

int main(int argc, char** argv) {
  return raylab_autograder_main(argc, argv, RAYLAB_VARIANT_DESCRIPTION, RAYLAB_VARIANT_DESCRIPTION_ZH);
}
