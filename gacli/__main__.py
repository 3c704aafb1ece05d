from gacli.cli import main

main()
