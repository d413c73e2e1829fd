fn main() {
    std::process::exit(pounding::cli::main_with_args(std::env::args_os()));
}
