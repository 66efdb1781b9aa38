/* peloid command-line driver (placeholder while the core is written). */
int main(void) { return 0; }
