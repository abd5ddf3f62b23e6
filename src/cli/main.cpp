// Placeholder entry point until the command modules land.
int main() { return 0; }
