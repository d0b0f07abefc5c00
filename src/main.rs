//! The `superlube` binary: parses the command line and runs one command of
//! [`superlube::cli`].

use clap::Parser;
use superlube::cli;

/// Whether `e` was caused by writing to a closed pipe (`superlube screen | head`).
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
            || c.downcast_ref::<csv::Error>().is_some_and(
                |ce| matches!(ce.kind(), csv::ErrorKind::Io(io) if io.kind() == std::io::ErrorKind::BrokenPipe),
            )
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let cli = match cli::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            // a mistyped flag whose nearest spelling is the wrong idea gets our tip
            if e.kind() == clap::error::ErrorKind::UnknownArgument {
                if let Some(t) = cli::tips::better(&e.render().to_string(), &args) {
                    eprint!("{t}");
                    std::process::exit(2);
                }
            }
            e.exit()
        }
    };
    for note in cli::renamed::notes(&args) {
        eprintln!("{note}");
    }
    if let Err(e) = cli::run(cli) {
        if is_broken_pipe(&e) {
            // The reader went away (`| head`): stop quietly, like other Unix tools.
            std::process::exit(0);
        }
        eprintln!("error: {e:#}");
        std::process::exit(2);
    }
}
