namespace polymech::io {}
