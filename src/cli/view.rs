//! `biped view`: serve the browser viewer and SSV modelling tool on a local address.

use crate::cli::out::{errln, outln};
use crate::cli::CliResult;
use biped_robots::lola::LolaType;
use biped_view::{serve, AppState, RobotSource, Server, ViewConfig};
use clap::Args;
use std::io::Write;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `biped view`.
#[derive(Args)]
#[command(long_about = VIEW_HELP)]
#[command(group(clap::ArgGroup::new("urdf_robot").args(["urdf", "robot"])))]
pub struct ViewArgs {
    /// Port to listen on (0: a free one).
    #[arg(long, default_value_t = 8765, allow_hyphen_values = true)]
    port: u16,
    /// IP address to listen on (or `localhost`); another than 127.0.0.1 serves other machines.
    #[arg(long, default_value = "127.0.0.1", allow_hyphen_values = true)]
    host: String,
    /// Show the Lola-like biped: `type2` or `type3` (without --urdf or --robot: type2).
    #[arg(long, value_name = "TYPE", conflicts_with_all = ["urdf", "robot"])]
    lola: Option<LolaType>,
    /// Show a described robot: `g1`, `talos` or a robot description FILE.toml (its URDF,
    /// floating base and SSV model, which without --ssv is shown but not saved).
    #[arg(long, value_name = "NAME")]
    robot: Option<String>,
    /// Show a URDF robot (its `<visual>` geometry).
    #[arg(long, value_name = "FILE")]
    urdf: Option<PathBuf>,
    /// Give the URDF root link a free joint named "root" (what `biped walk`/`simulate` use).
    #[arg(long, requires = "urdf")]
    floating: bool,
    /// Folder to look up `package://PKG/...` files in, before ROS_PACKAGE_PATH (repeatable).
    #[arg(long = "package-path", value_name = "DIR", requires = "urdf_robot")]
    package_path: Vec<PathBuf>,
    /// Collision-model file (TOML) to show and edit in place.
    #[arg(long, value_name = "FILE")]
    ssv: Option<PathBuf>,
    /// What `biped walk` or `biped simulate` wrote (a folder or one CSV table) to play back.
    #[arg(long, value_name = "DIR")]
    recording: Option<PathBuf>,
    /// Folder of the built page (default: web/dist of this source tree).
    #[arg(long, value_name = "DIR")]
    web: Option<PathBuf>,
}

const VIEW_HELP: &str = "\
Serve the viewer and SSV modelling tool: open the printed address in a browser.

The first line of stdout is `serving http://HOST:PORT/`. The page shows the robot (Lola's link
boxes, a URDF's visual geometry or a described robot's URDF), the collision model (--ssv, edited
in place: a save is checked with the loader of `biped ssv model` and written only if it loads;
with --robot alone the description's model, shown and checked, not saved) and plays back a
recording (--recording: the output folder of `biped walk` or `biped simulate`). Ctrl-C stops.
The page is built from web/ with `npm ci && npm run build` (Node.js and npm); the JSON API
under /api/ (documented in the biped_view crate) works without it.";

fn robot_source(args: &ViewArgs) -> Result<RobotSource, String> {
    if let Some(name) = &args.robot {
        return Ok(RobotSource::Description {
            file: crate::cli::bench_ik::robot_file(name)?,
            package_path: args.package_path.clone(),
        });
    }
    match (&args.urdf, args.lola) {
        (Some(path), _) => Ok(RobotSource::Urdf {
            path: path.clone(),
            floating: args.floating,
            package_path: args.package_path.clone(),
        }),
        (None, Some(variant)) => Ok(RobotSource::Lola(variant)),
        (None, None) => Ok(RobotSource::Lola(LolaType::Type2)),
    }
}

fn address(args: &ViewArgs) -> Result<SocketAddr, String> {
    let ip: IpAddr = match args.host.as_str() {
        "localhost" => Ipv4Addr::LOCALHOST.into(),
        host => host.parse().map_err(|_| {
            format!("--host: `{host}` is not an IP address (e.g. 127.0.0.1, ::1 or 0.0.0.0)")
        })?,
    };
    Ok(SocketAddr::new(ip, args.port))
}

/// Loads, binds, prints the address and serves until Ctrl-C (or SIGTERM).
pub fn run(args: ViewArgs) -> CliResult {
    let config = ViewConfig {
        robot: robot_source(&args)?,
        ssv: args.ssv.clone(),
        recording: args.recording.clone(),
        web_dir: args
            .web
            .clone()
            .unwrap_or_else(|| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/web/dist"))),
    };
    let addr = address(&args)?;
    let state = AppState::load(&config)?;
    for w in &state.robot.warnings {
        errln!("warning: {w}");
    }
    if !config.web_dir.join("index.html").is_file() {
        let dir = config.web_dir.display();
        errln!("warning: {dir}/index.html is missing: build the page with `npm ci && npm run build` in web/");
    }
    let server = Server::bind(addr, state)
        .map_err(|e| format!("--port {}: cannot listen on {addr}: {e}", args.port))?;
    let bound = server.local_addr()?;
    outln!("serving http://{bound}/")?;
    std::io::stdout().flush()?;
    let (tx, rx) = std::sync::mpsc::channel();
    let mut asked = false;
    ctrlc::set_handler(move || {
        if asked {
            std::process::exit(130);
        }
        asked = true;
        let _ = tx.send(());
    })?;
    serve(server, rx)?;
    errln!("stopped");
    Ok(ExitCode::SUCCESS)
}
