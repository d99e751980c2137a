"""Reports of a solved instant: the contract's JSON answer (`json_answer`, `json_text`), plain
values (`values`), and the terminal's tables of answers, instant centres and assemblies."""
