// Depth only: the fixed-function depth write is the whole output.
void main() {}
