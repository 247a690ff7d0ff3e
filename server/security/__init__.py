"""Who may call the console and how much: client identity, credentials, same-origin rules, limits, log redaction.
`Guard` (guard.py) applies them to every HTTP request and websocket; `create_app` installs it."""
