; exact_loop_asm: the exact mapper's inner loop with the x87 per-pixel divide; twin of
; kernel/mappers/exact.cpp (exact_loop), which it matches bit for bit: the same double operations
; in the same order (the x87 runs at 53-bit precision), the same saturating floor, the same wrap.

bits 32

%include "exact.inc"
%include "loop.inc"

section .text

; plane value (a0 + gy*y) + gx*x -> st0, for the plane at [ebx + %1]; x, y from the args block
%macro PLANE 1
    fld qword [ebx + EXACT_y]
    fmul qword [ebx + %1 + 16]      ; gy * y
    fadd qword [ebx + %1]           ; a0 + gy*y
    fld qword [ebx + EXACT_x]
    fmul qword [ebx + %1 + 8]       ; gx * x
    faddp st1, st0                  ; (a0 + gy*y) + gx*x
%endmacro

; floor of st0 (popped) -> eax, saturating, NaN -> 0; %1 is a unique label prefix. FIST rounds
; down under the control word at [esp + 8] (the caller's at [esp + 12] is back after it); it gives
; 0x80000000 for NaN, for a value beyond int32 and for a floor of -2^31, which FTST tells apart.
%macro FLOOR_I32 1
    fldcw [esp + 8]
    fist dword [esp]
    fldcw [esp + 12]
    mov eax, [esp]
    cmp eax, 0x80000000
    jne %1_pop
    ftst
    fnstsw ax
    fstp st0
    sahf
    mov eax, 0
    jp %1_done                      ; NaN
    mov eax, 0x7FFFFFFF
    ja %1_done                      ; above 0: at or beyond INT32_MAX
    mov eax, 0x80000000             ; at or below INT32_MIN
    jmp %1_done
%1_pop:
    fstp st0
%1_done:
%endmacro

; wrap or clamp eax into [0, %1) where %1 is a register or memory size; clobbers edx
%macro WRAP 2
    cmp dword [ebx + EXACT_clamp], 0
    jne %2_clamp
    cdq
    idiv dword %1                   ; edx = remainder, with the dividend's sign
    mov eax, edx
    test eax, eax
    jns %2_done
    add eax, %1
    jmp %2_done
%2_clamp:
    test eax, eax
    jns %2_not_negative
    xor eax, eax
%2_not_negative:
    cmp eax, %1
    jl %2_done
    mov eax, %1
    dec eax
%2_done:
%endmacro

global exact_loop_asm
exact_loop_asm:
    LOOP_ENTER 16 + EXACT_ARGS_SIZE   ; [esp]: integer scratch; [esp+8], [esp+12]: the control
                                      ; words (rounding down, the caller's); [esp+16]: a copy of the args
    fnstcw [esp + 12]
    mov ax, [esp + 12]
    and ax, 0xF3FF
    or ax, 0x0400                     ; RC = 01: toward -infinity
    mov [esp + 8], ax
    ; copy the block: x and y advance in the copy, the caller's stays untouched
    mov esi, LOOP_ARG(16 + EXACT_ARGS_SIZE)
    lea edi, [esp + 16]
    mov ecx, EXACT_ARGS_SIZE / 4
    rep movsd
    lea ebx, [esp + 16]
    ; ebx: args copy; edi: destination; ebp: pixels left
    mov edi, [ebx + EXACT_dst]
    mov ebp, [ebx + EXACT_count]
    test ebp, ebp
    jle .done
.pixel:
    PLANE EXACT_q                   ; st0 = q
    PLANE EXACT_pu                  ; st0 = pu, st1 = q
    fdiv st0, st1                   ; u = pu / q
    FLOOR_I32 .u
    mov esi, eax                    ; esi = tu
    PLANE EXACT_pv                  ; st0 = pv, st1 = q
    fdivrp st1, st0                 ; v = pv / q (pops q)
    FLOOR_I32 .v
    WRAP [ebx + EXACT_height], .wv  ; eax = row
    imul eax, [ebx + EXACT_width]
    mov ecx, eax                    ; ecx = row * width
    mov eax, esi
    WRAP [ebx + EXACT_width], .wu   ; eax = column
    add eax, ecx
    mov edx, [ebx + EXACT_texels]
    mov al, [edx + eax]
    mov [edi], al
    add edi, [ebx + EXACT_stride]
    fld qword [ebx + EXACT_x]       ; x += step_x; y += step_y
    fadd qword [ebx + EXACT_step_x]
    fstp qword [ebx + EXACT_x]
    fld qword [ebx + EXACT_y]
    fadd qword [ebx + EXACT_step_y]
    fstp qword [ebx + EXACT_y]
    dec ebp
    jnz .pixel
.done:
    LOOP_LEAVE 16 + EXACT_ARGS_SIZE
