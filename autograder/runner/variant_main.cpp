// main() of one autograder variant: only the description differs (RAYLAB_VARIANT_DESCRIPTION, and
// RAYLAB_VARIANT_DESCRIPTION_ZH for --lang zh), and the student's grader names the folder of the
// stage code it grades (RAYLAB_VARIANT_STAGE_FOLDER), to warn when that code is newer than the build.
int raylab_autograder_main(int argc, char** argv, const char* description, const char* description_zh,
                           const char* stage_folder);

#ifndef RAYLAB_VARIANT_STAGE_FOLDER
#define RAYLAB_VARIANT_STAGE_FOLDER nullptr
#endif

int main(int argc, char** argv) {
  return raylab_autograder_main(argc, argv, RAYLAB_VARIANT_DESCRIPTION, RAYLAB_VARIANT_DESCRIPTION_ZH,
                                RAYLAB_VARIANT_STAGE_FOLDER);
}
