// modexlab-native32: exits 0 where it runs, as a 32-bit static program: run32's probe of whether
// this machine's kernel runs 32-bit programs natively.
int main() { return sizeof(void*) == 4 ? 0 : 1; }
