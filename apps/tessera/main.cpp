// Placeholder entry point; subcommands land in this directory.
int main() { return 0; }
