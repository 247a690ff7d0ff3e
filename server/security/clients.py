"""The client a request comes from: the TCP peer, or the address a configured proxy says it forwarded."""

from __future__ import annotations

import ipaddress
from collections.abc import Iterable

from starlette.datastructures import Headers
from starlette.types import Scope

# One key for every request whose peer the server replaced from an untrusted X-Forwarded-For (see below).
UNKNOWN_FORWARDED = "forwarded-by-untrusted-peer"

Network = ipaddress.IPv4Network | ipaddress.IPv6Network


def parse_networks(proxies: Iterable[str]) -> tuple[Network, ...]:
    """SPARK_TRUSTED_PROXIES entries (IPs or CIDRs) as networks; a malformed entry is an error, not ignored."""
    out = []
    for p in proxies:
        try:
            out.append(ipaddress.ip_network(p.strip(), strict=False))
        except ValueError:
            raise ValueError(f"SPARK_TRUSTED_PROXIES: {p!r} is not an IP address or network") from None
    return tuple(out)


def _host(hop: str) -> str:
    """'1.2.3.4:80' -> '1.2.3.4', '[::1]:80' -> '::1'; anything else as is."""
    if hop.startswith("[") and "]" in hop:
        return hop[1 : hop.index("]")]
    return hop.rsplit(":", 1)[0] if hop.count(":") == 1 else hop


def _trusted(host: str, networks: tuple[Network, ...]) -> bool:
    try:
        address = ipaddress.ip_address(host)
    except ValueError:
        return False
    return any(address in n for n in networks)


def client_address(scope: Scope, trusted: tuple[Network, ...]) -> str:
    """The key rate limits count against. X-Forwarded-For counts only when the peer is a trusted proxy; then
    the nearest hop that no trusted proxy added is the client."""
    peer = scope["client"][0] if scope.get("client") else "?"
    values = Headers(scope=scope).getlist("x-forwarded-for")
    hops = [_host(h.strip()) for v in values for h in v.split(",") if h.strip()]
    if not hops:
        return peer
    if trusted and _trusted(peer, trusted):
        return next((h for h in reversed(hops) if not _trusted(h, trusted)), hops[0])
    if not trusted and peer in hops:
        # The server already replaced the peer with a hop of this header (uvicorn's --proxy-headers trusts
        # 127.0.0.1 by default), so the real peer is unknown: all such requests share one key, and varying
        # the header gains nothing. `spark serve` turns that uvicorn feature off (server.security.serving).
        return UNKNOWN_FORWARDED
    return peer
