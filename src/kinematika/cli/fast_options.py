"""The fast command line's options (`fast`): each command's options as typer reads them.

GENERATED from the typer commands by `python -m kinematika.cli.generate_options`: do not edit.
Change the typer command, then run that command (tests/core/test_fast_paths.py
regenerates this module and compares).

Each option: (the parameter of `run.<command>_command`, its kind[, smallest, largest]).
"""

OPTIONS: dict[str, dict[str, tuple]] = {
    'solve': {
        '--json': ('as_json', 'flag'),
        '--symbolic': ('symbolic', 'flag'),
    },
    'centres': {
        '--json': ('as_json', 'flag'),
        '--symbolic': ('symbolic', 'flag'),
    },
    'sweep': {
        '--joint': ('joint', 'text'),
        '--by': ('by', 'float'),
        '--steps': ('steps', 'int', 1, 10000000),
        '--json': ('as_json', 'flag'),
        '--csv': ('csv', 'path'),
        '--skip-bad': ('skip_bad', 'flag'),
        '--plot': ('plot', 'path'),
        '-o': ('output', 'path'),
        '--output': ('output', 'path'),
        '--format': ('fmt', 'text'),
    },
    'simulate': {
        '--time': ('time', 'float'),
        '--steps': ('steps', 'int', 1, 1000000),
        '--method': ('method', 'text'),
        '--json': ('as_json', 'flag'),
        '--csv': ('csv', 'path'),
        '--plot': ('plot', 'path'),
        '--animate': ('animation', 'path'),
        '-o': ('output', 'path'),
        '--output': ('output', 'path'),
        '--format': ('fmt', 'text'),
    },
}
