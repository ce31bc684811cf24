// The header the bad include names (exists, so only the direction is wrong).
#pragma once
