//! The page's files, built into the binary: the only paths the web server
//! answers besides `/ws`. No path from a request reaches the file system.

/// One file of the page.
pub struct Asset {
    pub path: &'static str,
    pub mime: &'static str,
    pub body: &'static [u8],
    /// The vendored files do not change within a build: browsers may keep
    /// them a day; the page and its glue are asked again each time.
    pub cache: &'static str,
}

const PAGE: &str = "no-cache";
const VENDOR: &str = "public, max-age=86400";

pub const ASSETS: &[Asset] = &[
    Asset {
        path: "/",
        mime: "text/html; charset=utf-8",
        body: include_bytes!("../../../web/index.html"),
        cache: PAGE,
    },
    Asset {
        path: "/app.js",
        mime: "text/javascript; charset=utf-8",
        body: include_bytes!("../../../web/app.js"),
        cache: PAGE,
    },
    Asset {
        path: "/phone.js",
        mime: "text/javascript; charset=utf-8",
        body: include_bytes!("../../../web/phone.js"),
        cache: PAGE,
    },
    Asset {
        path: "/xterm.js",
        mime: "text/javascript; charset=utf-8",
        body: include_bytes!("../../../web/vendor/xterm/xterm.js"),
        cache: VENDOR,
    },
    Asset {
        path: "/xterm.css",
        mime: "text/css; charset=utf-8",
        body: include_bytes!("../../../web/vendor/xterm/xterm.css"),
        cache: VENDOR,
    },
    Asset {
        path: "/addon-fit.js",
        mime: "text/javascript; charset=utf-8",
        body: include_bytes!("../../../web/vendor/addon-fit/addon-fit.js"),
        cache: VENDOR,
    },
    Asset {
        path: "/LICENSE-xterm.txt",
        mime: "text/plain; charset=utf-8",
        body: include_bytes!("../../../web/vendor/xterm/LICENSE"),
        cache: VENDOR,
    },
];

/// The file at `path` (`/index.html` is `/`), if the page has one.
pub fn find(path: &str) -> Option<&'static Asset> {
    let path = if path == "/index.html" { "/" } else { path };
    ASSETS.iter().find(|a| a.path == path)
}

/// The bytes a browser loads for the page: all its files.
pub fn page_bytes() -> usize {
    ASSETS
        .iter()
        .filter(|a| !a.path.starts_with("/LICENSE"))
        .map(|a| a.body.len())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_pages_files_are_found() {
        assert!(find("/").is_some());
        assert_eq!(find("/index.html").map(|a| a.path), Some("/"));
        for p in [
            "/../Cargo.toml",
            "/etc/passwd",
            "//xterm.js",
            "/XTERM.JS",
            "/ws",
            "",
        ] {
            assert!(find(p).is_none(), "{p}");
        }
        // The page loads every script and style it names, and nothing else.
        let page = std::str::from_utf8(find("/").unwrap().body).unwrap();
        for a in [
            "/xterm.js",
            "/addon-fit.js",
            "/phone.js",
            "/app.js",
            "/xterm.css",
        ] {
            assert!(page.contains(&format!("\"{a}\"")), "{a}");
        }
        assert!(!page.contains("http"), "no address outside the server");
        assert!(page_bytes() > 400_000 && page_bytes() < 600_000);
    }
}
