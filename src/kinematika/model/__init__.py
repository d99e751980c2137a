"""The model: a mechanism file (YAML, TOML or JSON) or a `Mechanism` built in Python, checked
against the contract's schema (`schema`, with the generated fast check `shape`) and turned into
the one parsed `model.Model` that every command and view shares (`build`): names resolved,
expressions parsed, nothing evaluated yet."""
