#pragma once
// Public API of the time-domain simulation, chatter detection and suppression advice.
#include "simulation/cvode_reference.h"
#include "simulation/milling_simulation.h"
#include "simulation/simulation_types.h"
#include "simulation/smith_tlusty.h"
