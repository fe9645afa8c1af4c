//! What the console says: the banner before the class (where to connect,
//! the same host form in the lecturer's and the students' commands; bound
//! to all interfaces, the machine's own addresses, a line each, so the
//! lecturer can write one on the board) and the goodbye's summary.

use std::net::{IpAddr, SocketAddr};
use std::path::PathBuf;

/// The machine's addresses a client on the network can reach when the
/// server listens on `bound` (0.0.0.0: the IPv4 ones; `::` both
/// families): loopback and IPv6 link-local ones left out unless nothing
/// else is there. From getifaddrs(3) (through nix).
pub fn addresses(bound: IpAddr) -> Vec<IpAddr> {
    let mut all: Vec<IpAddr> = nix::ifaddrs::getifaddrs()
        .map(|it| {
            it.filter_map(|i| {
                let a = i.address?;
                if let Some(v4) = a.as_sockaddr_in() {
                    Some(IpAddr::V4(v4.ip()))
                } else {
                    a.as_sockaddr_in6().map(|v6| IpAddr::V6(v6.ip()))
                }
            })
            .collect()
        })
        .unwrap_or_default();
    all.retain(|a| bound.is_ipv6() || a.is_ipv4());
    all.sort();
    all.dedup();
    let link_local =
        |a: &IpAddr| matches!(a, IpAddr::V6(v6) if v6.segments()[0] & 0xffc0 == 0xfe80);
    let reachable: Vec<IpAddr> = all
        .iter()
        .copied()
        .filter(|a| !a.is_loopback() && !link_local(a))
        .collect();
    if reachable.is_empty() {
        all.retain(IpAddr::is_loopback);
        return all;
    }
    reachable
}

/// The banner's lines about where to connect: the addresses when bound to
/// all interfaces, then the lecturer's command (if any) and the
/// students', both with the same host: the one address there is, or
/// `HOST` standing for one of those listed. `extra` comes between them
/// (the class code, the log).
pub fn lines(addr: SocketAddr, lecturer: Option<&str>, extra: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    let host = if addr.ip().is_unspecified() {
        let found = addresses(addr.ip());
        match found.as_slice() {
            [one] => one.to_string(),
            _ => {
                out.push("this machine's addresses (HOST below is one of them):".into());
                out.extend(found.iter().map(|a| format!("  {a}")));
                "HOST".to_string()
            }
        }
    } else {
        addr.ip().to_string()
    };
    let port = addr.port();
    match lecturer {
        Some(user) => out.push(format!("lecturer: ssh -p {port} {user}@{host}")),
        None => out.push("no --lecturer-keys: everyone explores alone".into()),
    }
    out.extend(extra.iter().cloned());
    out.push(format!("students: ssh -p {port} {host}"));
    out
}

/// The web page's address for a class: `http://HOST:PORT/`, with
/// `?code=WORD` when the class has a code, for the banner's QR code and
/// the lecturer's `Q`. On all interfaces HOST is the first of the
/// machine's addresses ([`addresses`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Join {
    pub url: String,
    /// Every address the page is reached at (bound to all interfaces:
    /// one per address of the machine).
    pub pages: Vec<String>,
}

pub fn join_url(addr: SocketAddr, code: Option<&super::code::ClassCode>) -> Join {
    let hosts: Vec<IpAddr> = if addr.ip().is_unspecified() {
        addresses(addr.ip())
    } else {
        vec![addr.ip()]
    };
    let page = |ip: &IpAddr| match ip {
        IpAddr::V6(v6) => format!("http://[{v6}]:{}/", addr.port()),
        IpAddr::V4(v4) => format!("http://{v4}:{}/", addr.port()),
    };
    let pages: Vec<String> = hosts.iter().map(page).collect();
    let first = pages
        .first()
        .cloned()
        .unwrap_or_else(|| format!("http://{addr}/"));
    let url = match code {
        Some(c) => format!("{first}?code={}", percent(c.as_str())),
        None => first,
    };
    Join { url, pages }
}

/// `s` with everything but unreserved URL characters as `%XX`.
fn percent(s: &str) -> String {
    s.bytes()
        .map(|b| {
            if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
                (b as char).to_string()
            } else {
                format!("%{b:02X}")
            }
        })
        .collect()
}

/// The banner's lines about the web page: its address(es) and the join
/// address the QR code (printed after them on a terminal) holds.
pub fn web_lines(addr: SocketAddr, join: &Join) -> Vec<String> {
    let mut out = vec![format!("web: listening on {addr}")];
    match join.pages.as_slice() {
        [one] => out.push(format!("students on the web: {one}")),
        many => {
            out.push("students on the web, at any of:".into());
            out.extend(many.iter().map(|p| format!("  {p}")));
        }
    }
    out.push(format!(
        "join address (the QR code; the lecturer's Q shows it): {}",
        join.url
    ));
    out
}

/// The console's last lines when the server stops.
pub fn summary(seen: u64, polls: u64, saved: &[PathBuf]) -> Vec<String> {
    let plural = |n: u64, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut out = vec![format!(
        "roughtui serve: the class has ended: {} came, {}",
        plural(seen, "student", "students"),
        plural(polls, "poll", "polls")
    )];
    if saved.is_empty() {
        out.push("no poll answers were saved".into());
    } else {
        out.push("poll answers saved in:".into());
        out.extend(saved.iter().map(|p| format!("  {}", p.display())));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_join_address_carries_the_code() {
        let a: SocketAddr = "192.0.2.7:8080".parse().unwrap();
        let code = crate::serve::code::ClassCode::word("gr än&it").unwrap();
        let j = join_url(a, Some(&code));
        assert_eq!(j.url, "http://192.0.2.7:8080/?code=gr%20%C3%A4n%26it");
        assert_eq!(j.pages, ["http://192.0.2.7:8080/"]);
        let j = join_url("[2001:db8::7]:80".parse().unwrap(), None);
        assert_eq!(j.url, "http://[2001:db8::7]:80/");
        let l = web_lines(a, &join_url(a, None));
        assert_eq!(
            l,
            [
                "web: listening on 192.0.2.7:8080",
                "students on the web: http://192.0.2.7:8080/",
                "join address (the QR code; the lecturer's Q shows it): http://192.0.2.7:8080/"
            ]
        );
    }

    #[test]
    fn both_commands_name_the_same_host() {
        let a: SocketAddr = "192.0.2.7:2222".parse().unwrap();
        let l = lines(a, Some("lecturer"), &["class code: on".into()]);
        assert_eq!(
            l,
            [
                "lecturer: ssh -p 2222 lecturer@192.0.2.7",
                "class code: on",
                "students: ssh -p 2222 192.0.2.7"
            ]
        );
        let any: SocketAddr = "0.0.0.0:2222".parse().unwrap();
        let l = lines(any, None, &[]);
        let found = addresses(any.ip());
        assert!(!found.is_empty());
        assert!(found.iter().all(IpAddr::is_ipv4));
        let last = l.last().unwrap();
        if let [one] = found.as_slice() {
            assert_eq!(last, &format!("students: ssh -p 2222 {one}"));
        } else {
            assert_eq!(last, "students: ssh -p 2222 HOST");
            for f in &found {
                assert!(l.contains(&format!("  {f}")), "{l:?}");
            }
        }
    }

    #[test]
    fn the_goodbye_sums_up() {
        assert_eq!(
            summary(1, 0, &[]),
            [
                "roughtui serve: the class has ended: 1 student came, 0 polls",
                "no poll answers were saved"
            ]
        );
        let s = summary(31, 3, &[PathBuf::from("/tmp/a.csv")]);
        assert_eq!(
            s[0],
            "roughtui serve: the class has ended: 31 students came, 3 polls"
        );
        assert_eq!(s[2], "  /tmp/a.csv");
    }
}
