/* viewer_file.h: Appendix B's first excerpt declares the program's globals
 * itself; it needs the chain's size. */
#define NBALLS 10
